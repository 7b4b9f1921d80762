#![no_main]

use libfuzzer_sys::fuzz_target;
use surftopo_intrinsic::geometry::{MAX_INPUT_BITS, Rational};
use surftopo_intrinsic::{
    DEFAULT_LENGTH_TOLERANCE, IntrinsicTriangulation, PortalgonDoc, TriangleStyle,
};

fuzz_target!(|data: &[u8]| {
    let Ok(doc) = PortalgonDoc::read(data) else {
        return;
    };
    // The same text from memory is the same document.
    assert_eq!(PortalgonDoc::from_slice(data).ok().as_ref(), Some(&doc));
    // Exact mode: every number within the input limit, the portalgon exact or a typed error;
    // written exactly, it reads back to the same values.
    if let Ok(exact) = doc.to_portalgon_in::<Rational>(0.0) {
        for s in exact.sides() {
            for c in exact.start(s) {
                assert!(c.bits() <= MAX_INPUT_BITS + 8, "{c}");
            }
        }
        let written = PortalgonDoc::from_portalgon(&exact).to_json().expect("finite");
        let back = PortalgonDoc::from_json(&written)
            .and_then(|d| d.to_portalgon_in::<Rational>(0.0))
            .expect("an exact portalgon written reads back");
        assert_eq!(back, exact);
    }
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
