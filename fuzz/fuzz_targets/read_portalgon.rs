#![no_main]

use libfuzzer_sys::fuzz_target;
use surftopo_intrinsic::{
    DEFAULT_LENGTH_TOLERANCE, IntrinsicTriangulation, PortalgonDoc, TriangleStyle,
};

fuzz_target!(|data: &[u8]| {
    let Ok(doc) = PortalgonDoc::read(data) else {
        return;
    };
    // Every conversion either fails with a typed error or gives a consistent result.
    if let Ok(portalgon) = doc.to_portalgon(DEFAULT_LENGTH_TOLERANCE) {
        assert!(portalgon.area().is_finite());
    }
    if let Ok(tri) = doc.to_triangulation(DEFAULT_LENGTH_TOLERANCE) {
        tri.mesh().check_invariants().expect("a read triangulation is a valid mesh");
        // What the reader accepts, the writer writes and the reader reads back, bit for bit.
        let mut bytes = Vec::new();
        tri.write_json(&mut bytes, TriangleStyle::Lengths)
            .expect("lengths of a read triangulation are finite");
        let back = IntrinsicTriangulation::read_json(&bytes[..], DEFAULT_LENGTH_TOLERANCE)
            .expect("written portalgon reads back");
        assert_eq!(back.lengths(), tri.lengths());
    }
});
