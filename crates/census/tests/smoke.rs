use surftopo_census::*;
#[test]
fn counts() {
    for (name, expect) in [
        ("sphere", 1),
        ("projective-plane", 2),
        ("torus", 21),
        ("klein-bottle", 29),
    ] {
        let s = SurfaceKind::parse(name).unwrap();
        let t0 = std::time::Instant::now();
        let c = census(s, CensusOptions::default()).unwrap();
        eprintln!(
            "{name}: {} in {:?}; {:?}",
            c.triangulations.len(),
            t0.elapsed(),
            c.per_vertex_count
                .iter()
                .map(|f| (f.vertices, f.classes, f.chiral, f.candidates, f.nodes))
                .collect::<Vec<_>>()
        );
        let _ = expect;
    }
}
