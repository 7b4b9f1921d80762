//! Reading and writing files by path: format from the extension, gzip for
//! `.gz`, atomic replacement of the target on write.

use std::ffi::OsString;
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufReader, Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use flate2::Compression;
use flate2::read::MultiGzDecoder;
use flate2::write::GzEncoder;

use crate::error::Ctx;
use crate::{Format, IoError, PolygonSoup, WriteOptions, is_gzip_path};

/// Reads a mesh file.
///
/// `path`: the file; its extension gives the format (`.obj`, `.off`, `.ply`,
/// `.stl`, case-insensitive) and a trailing `.gz` means gzip-compressed,
/// e.g. `bunny.off.gz`. Error messages name the path as given.
pub fn read_path(path: &Path) -> Result<PolygonSoup, IoError> {
    let name = path.display().to_string();
    let format =
        Format::from_path(path).ok_or_else(|| IoError::UnsupportedFormat { path: name.clone() })?;
    let ctx = Ctx { name: &name };
    let bytes = load(path, is_gzip_path(path)).map_err(|e| ctx.io(e))?;
    crate::read_bytes(&bytes, format, &name)
}

/// Reads the whole file, decompressing if `gz`.
fn load(path: &Path, gz: bool) -> io::Result<Vec<u8>> {
    let mut file = File::open(path)?;
    let len = file.metadata().map(|m| m.len()).unwrap_or(0);
    let mut bytes = Vec::new();
    if gz {
        // The gzip trailer holds the uncompressed size mod 2^32: a capacity
        // hint, capped at 32 times the compressed size.
        if len >= 18 {
            file.seek(SeekFrom::End(-4))?;
            let mut isize = [0u8; 4];
            file.read_exact(&mut isize)?;
            file.seek(SeekFrom::Start(0))?;
            let hint = u64::from(u32::from_le_bytes(isize)).min(len.saturating_mul(32));
            bytes.reserve(usize::try_from(hint).unwrap_or(0));
        }
        MultiGzDecoder::new(BufReader::with_capacity(1 << 16, file)).read_to_end(&mut bytes)?;
    } else {
        bytes.reserve(usize::try_from(len).unwrap_or(0));
        file.read_to_end(&mut bytes)?;
    }
    Ok(bytes)
}

/// Writes a mesh file atomically.
///
/// `path`: the target; its extension gives the format (`.obj`, `.off`,
/// `.ply`) and a trailing `.gz` compresses; `soup`: what to write (checked
/// first, see [`PolygonSoup::validate`]); `options`: PLY encoding (binary
/// little endian by default) and gzip level. The data goes to a temporary
/// file `.name.tmp-<pid>-<n>` in the same directory, which is synced and then
/// renamed over `path`; on any error the temporary file is removed and
/// `path` is left as it was.
pub fn write_path(path: &Path, soup: &PolygonSoup, options: &WriteOptions) -> Result<(), IoError> {
    let name = path.display().to_string();
    let format =
        Format::from_path(path).ok_or_else(|| IoError::UnsupportedFormat { path: name.clone() })?;
    crate::check_writable(soup, format)?;
    let gz = is_gzip_path(path);
    let level = Compression::new(options.gzip_level.min(9));
    atomic_write(path, |file| {
        if gz {
            let enc = crate::write_unchecked(GzEncoder::new(file, level), soup, format, options)?;
            enc.finish()
        } else {
            crate::write_unchecked(file, soup, format, options)
        }
    })
    .map_err(|e| Ctx { name: &name }.io(e))
}

/// Counter making temporary names unique within the process.
static TMP_COUNTER: AtomicU64 = AtomicU64::new(0);

/// Temporary sibling of `path`: `.name.tmp-<pid>-<n>`.
fn temp_path(path: &Path) -> io::Result<PathBuf> {
    let file_name = path
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "path has no file name"))?;
    let mut tmp = OsString::from(".");
    tmp.push(file_name);
    tmp.push(format!(
        ".tmp-{}-{}",
        std::process::id(),
        TMP_COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    Ok(path.with_file_name(tmp))
}

/// Runs `fill` on a new temporary file next to `path`, syncs it and renames
/// it over `path`; removes the temporary file on any error.
pub fn atomic_write(path: &Path, fill: impl FnOnce(File) -> io::Result<File>) -> io::Result<()> {
    let tmp = temp_path(path)?;
    let file = OpenOptions::new().write(true).create_new(true).open(&tmp)?;
    let result = (|| {
        if let Ok(meta) = fs::metadata(path) {
            // Keep the permissions of the file being replaced.
            let _ = file.set_permissions(meta.permissions());
        }
        let mut file = fill(file)?;
        file.flush()?;
        file.sync_all()?;
        drop(file);
        fs::rename(&tmp, path)
    })();
    if let Err(e) = result {
        let _ = fs::remove_file(&tmp);
        return Err(e);
    }
    // Make the rename durable; best effort.
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if let Ok(d) = File::open(dir) {
        let _ = d.sync_all();
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entries(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn failed_fill_leaves_target_and_no_temp() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("m.obj");
        fs::write(&target, b"old").unwrap();
        let err = atomic_write(&target, |mut f| {
            f.write_all(b"partial")?;
            Err(io::Error::other("boom"))
        })
        .unwrap_err();
        assert_eq!(err.to_string(), "boom");
        assert_eq!(fs::read(&target).unwrap(), b"old");
        assert_eq!(entries(dir.path()), ["m.obj"]);
    }

    #[test]
    fn success_replaces_target() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("m.obj");
        fs::write(&target, b"old").unwrap();
        atomic_write(&target, |mut f| {
            f.write_all(b"new")?;
            Ok(f)
        })
        .unwrap();
        assert_eq!(fs::read(&target).unwrap(), b"new");
        assert_eq!(entries(dir.path()), ["m.obj"]);
    }
}
