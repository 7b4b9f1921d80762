//! Buffered output with number formatting shared by the writers.

use std::io::{self, Write};

const CHUNK: usize = 1 << 16;

/// Accumulates output in a buffer and hands it to the writer in chunks.
pub(crate) struct Out<W: Write> {
    w: W,
    buf: Vec<u8>,
}

impl<W: Write> Out<W> {
    pub fn new(w: W) -> Self {
        Out {
            w,
            buf: Vec::with_capacity(CHUNK + 1024),
        }
    }

    /// Passes the buffer on once it is full; call after each record.
    #[inline]
    pub fn flush_if_full(&mut self) -> io::Result<()> {
        if self.buf.len() >= CHUNK {
            self.w.write_all(&self.buf)?;
            self.buf.clear();
        }
        Ok(())
    }

    /// Writes what is left, flushes and returns the writer.
    pub fn finish(mut self) -> io::Result<W> {
        self.w.write_all(&self.buf)?;
        self.w.flush()?;
        Ok(self.w)
    }

    #[inline]
    pub fn bytes(&mut self, b: &[u8]) {
        self.buf.extend_from_slice(b);
    }

    #[inline]
    pub fn byte(&mut self, b: u8) {
        self.buf.push(b);
    }

    /// Shortest decimal that reads back to the same bits (`-0` and subnormals included;
    /// [`surftopo_mesh::decimal::push_f64`]) without a trailing `.0`; exponent form for very
    /// large or small values.
    #[inline]
    pub fn f64(&mut self, x: f64) {
        surftopo_mesh::decimal::push_f64(&mut self.buf, x);
        if self.buf.ends_with(b".0") {
            self.buf.truncate(self.buf.len() - 2);
        }
    }

    /// [`Self::f64`] for an `f32`: the shortest decimal reading back to the same `f32` bits.
    #[inline]
    pub fn f32(&mut self, x: f32) {
        surftopo_mesh::decimal::push_f32(&mut self.buf, x);
        if self.buf.ends_with(b".0") {
            self.buf.truncate(self.buf.len() - 2);
        }
    }

    /// One text line `prefix x y z` of a vertex position.
    #[inline]
    pub fn point_line(&mut self, prefix: &[u8], p: [f64; 3]) -> io::Result<()> {
        self.bytes(prefix);
        self.f64(p[0]);
        self.byte(b' ');
        self.f64(p[1]);
        self.byte(b' ');
        self.f64(p[2]);
        self.byte(b'\n');
        self.flush_if_full()
    }

    /// The rest of a face's text line: ` i1 i2 ...` (each index plus `base`), then a newline.
    #[inline]
    pub fn index_line(&mut self, face: &[u32], base: u64) -> io::Result<()> {
        for &i in face {
            self.byte(b' ');
            self.u64(u64::from(i) + base);
        }
        self.byte(b'\n');
        self.flush_if_full()
    }

    #[inline]
    pub fn u64(&mut self, v: u64) {
        surftopo_mesh::decimal::push_u64(&mut self.buf, v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fmt(x: f64) -> String {
        let mut o = Out::new(Vec::new());
        o.f64(x);
        String::from_utf8(o.finish().unwrap()).unwrap()
    }

    #[test]
    fn floats() {
        assert_eq!(fmt(1.0), "1");
        assert_eq!(fmt(-0.0), "-0");
        assert_eq!(fmt(0.1), "0.1");
        assert_eq!(fmt(1e308), "1e+308");
        assert_eq!(fmt(5e-324), "5e-324");
        let mut o = Out::new(Vec::new());
        o.u64(0);
        o.byte(b' ');
        o.u64(u64::MAX);
        assert_eq!(o.finish().unwrap(), b"0 18446744073709551615");
    }
}
