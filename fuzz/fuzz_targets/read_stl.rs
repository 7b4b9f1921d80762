#![no_main]

use libfuzzer_sys::fuzz_target;
use surftopo_io::{Format, read};

fuzz_target!(|data: &[u8]| {
    if let Ok(soup) = read(data, Format::Stl, "fuzz") {
        // Whatever a reader accepts must be a consistent soup.
        assert!(soup.validate().is_ok());
    }
});
