#![no_main]

use libfuzzer_sys::fuzz_target;
use surftopo_io::{Format, IoError, ReadLimits, decompress_gzip, read_bytes};

/// Small enough that bombs in the corpus hit it quickly.
const LIMIT: u64 = 1 << 20;

fuzz_target!(|data: &[u8]| {
    let limits = ReadLimits { max_bytes: LIMIT };
    match decompress_gzip(data, &limits, "fuzz.obj.gz") {
        Ok(bytes) => {
            // Never more than the limit, and what comes out parses or fails with a typed error.
            assert!(bytes.len() as u64 <= LIMIT);
            if let Ok(soup) = read_bytes(&bytes, Format::Obj, "fuzz.obj") {
                assert!(soup.validate().is_ok());
            }
        }
        Err(IoError::InputTooLarge { limit, .. }) => assert_eq!(limit, LIMIT),
        Err(IoError::Io { .. } | IoError::OutOfMemory { .. }) => {}
        Err(other) => panic!("unexpected error {other:?}"),
    }
});
