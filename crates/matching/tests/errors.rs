//! Invalid inputs are refused with an error naming the offending edge or node.

use surftopo_matching::{CubicGraph, GraphError};

#[test]
fn bridge_is_named() {
    // Two triangles with one doubled side, joined by the single edge 4.
    let edges = vec![
        [0, 1],
        [0, 1],
        [0, 2],
        [1, 2],
        [2, 5],
        [3, 4],
        [3, 4],
        [3, 5],
        [4, 5],
    ];
    assert_eq!(
        CubicGraph::new(6, edges).unwrap_err(),
        GraphError::Bridge {
            edge: 4,
            endpoints: [2, 5]
        }
    );
    // A bridge between two larger blocks.
    let mut edges = Vec::new();
    // Left block: K4 with edge 0-1 subdivided by node 4; node 4's third edge is the bridge.
    edges.extend([[0, 4], [4, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]);
    // Right block: the same on 5..=9, node 9 subdividing 5-6.
    edges.extend([[5, 9], [9, 6], [5, 7], [5, 8], [6, 7], [6, 8], [7, 8]]);
    edges.push([4, 9]); // edge 14
    assert_eq!(
        CubicGraph::new(10, edges).unwrap_err(),
        GraphError::Bridge {
            edge: 14,
            endpoints: [4, 9]
        }
    );
}

#[test]
fn wrong_degree_is_named() {
    // Degree 2 at node 3 (and 1 at node 2): K4 minus edge 2-3 plus nothing.
    let edges = vec![[0, 1], [0, 2], [0, 3], [1, 2], [1, 3]];
    assert_eq!(
        CubicGraph::new(4, edges).unwrap_err(),
        GraphError::WrongDegree { node: 2, degree: 2 }
    );
    // Degree 4 at node 0.
    let edges = vec![[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3], [0, 1]];
    assert_eq!(
        CubicGraph::new(4, edges).unwrap_err(),
        GraphError::WrongDegree { node: 0, degree: 4 }
    );
}

#[test]
fn loop_is_named() {
    let edges = vec![[0, 1], [0, 1], [0, 1], [2, 2], [2, 3], [3, 3]];
    assert_eq!(
        CubicGraph::new(4, edges).unwrap_err(),
        GraphError::Loop { edge: 3, node: 2 }
    );
}

#[test]
fn disconnected_is_named() {
    let edges = vec![[0, 1], [0, 1], [1, 0], [2, 3], [3, 2], [2, 3]];
    assert_eq!(
        CubicGraph::new(4, edges).unwrap_err(),
        GraphError::Disconnected { node: 2 }
    );
}

#[test]
fn empty_and_out_of_range() {
    assert_eq!(CubicGraph::new(0, vec![]).unwrap_err(), GraphError::Empty);
    assert_eq!(
        CubicGraph::new(2, vec![[0, 1], [0, 1], [0, 2]]).unwrap_err(),
        GraphError::NodeOutOfRange {
            edge: 2,
            node: 2,
            node_count: 2
        }
    );
}

#[test]
fn errors_print_the_offender() {
    let e = GraphError::Bridge {
        edge: 14,
        endpoints: [4, 9],
    };
    assert!(e.to_string().contains("edge 14"));
    let e = GraphError::WrongDegree { node: 7, degree: 4 };
    assert!(e.to_string().contains("node 7"));
}
