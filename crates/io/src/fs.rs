//! Reading and writing files by path: format from the extension, gzip for
//! `.gz`, atomic replacement of the target on write.

use std::ffi::OsString;
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufRead, BufReader, Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};

use flate2::Compression;
use flate2::bufread::GzDecoder;
use flate2::write::GzEncoder;

use crate::error::Ctx;
use crate::{Format, IoError, PolygonSoup, WriteOptions, is_gzip_path};

/// Default [`ReadLimits::max_bytes`]: 1 GiB of (decompressed) input, about what a mesh of 25
/// million faces takes as OBJ; the soup read from it takes at most about three times as much.
pub const DEFAULT_MAX_INPUT_BYTES: u64 = 1 << 30;

/// Bounds on what reading a file may hold in memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ReadLimits {
    /// The most bytes an input may have after decompression. Reading stops with
    /// [`IoError::InputTooLarge`] as soon as more arrive, so a gzip bomb or `/dev/zero` costs at
    /// most this much memory; what a header or a gzip trailer claims is never trusted.
    pub max_bytes: u64,
}

impl Default for ReadLimits {
    fn default() -> Self {
        ReadLimits {
            max_bytes: DEFAULT_MAX_INPUT_BYTES,
        }
    }
}

/// Reads a mesh file within the default [`ReadLimits`].
///
/// `path`: the file; its extension gives the format (`.obj`, `.off`, `.ply`,
/// `.stl`, case-insensitive) and a trailing `.gz` means gzip-compressed,
/// e.g. `bunny.off.gz`. Error messages name the path as given (control
/// characters escaped).
pub fn read_path(path: &Path) -> Result<PolygonSoup, IoError> {
    read_path_with(path, &ReadLimits::default())
}

/// [`read_path`] within `limits`.
///
/// # Errors
/// As [`read_path`]; [`IoError::InputTooLarge`] beyond `limits.max_bytes`.
pub fn read_path_with(path: &Path, limits: &ReadLimits) -> Result<PolygonSoup, IoError> {
    read_path_with_non_finite(path, limits, crate::NonFinite::Refuse)
}

/// [`read_path_with`], with `non_finite` saying whether NaN and infinite coordinates are
/// refused or kept ([`crate::read_bytes_with`]).
///
/// # Errors
/// As [`read_path_with`].
pub fn read_path_with_non_finite(
    path: &Path,
    limits: &ReadLimits,
    non_finite: crate::NonFinite,
) -> Result<PolygonSoup, IoError> {
    let name = path_name(path);
    let format =
        Format::from_path(path).ok_or_else(|| IoError::UnsupportedFormat { path: name.clone() })?;
    let bytes = load_path(path, limits)?;
    crate::read_bytes_with(&bytes, format, &name, non_finite)
}

/// Reads a mesh file within `limits` (non-finite coordinates as `non_finite` says), its format
/// from the extension when it has one (as [`read_path_with`]) and otherwise from the content ([`crate::sniff_format`], after
/// decompressing gzip data told by its magic); returns the soup and the format read.
///
/// # Errors
/// As [`read_path_with`]; [`IoError::UnknownContent`] when neither the name nor the content says
/// the format.
pub fn read_path_detected(
    path: &Path,
    limits: &ReadLimits,
    non_finite: crate::NonFinite,
) -> Result<(PolygonSoup, Format), IoError> {
    let name = path_name(path);
    let bytes = load_path(path, limits)?;
    match Format::from_path(path) {
        Some(format) => Ok((
            crate::read_bytes_with(&bytes, format, &name, non_finite)?,
            format,
        )),
        None if crate::is_gzip(&bytes) && !is_gzip_path(path) => {
            let inner = decompress_gzip(&bytes[..], limits, &name)?;
            drop(bytes);
            read_bytes_detected(&inner, &name, non_finite)
        }
        None => read_bytes_detected(&bytes, &name, non_finite),
    }
}

/// Parses an uncompressed mesh file held in memory, its format told by its content
/// ([`crate::sniff_format`]); returns the soup and the format read. `name`: the input's name in
/// error messages.
///
/// # Errors
/// [`IoError::UnknownContent`], or the reader's errors as [`crate::read_bytes`].
pub fn read_bytes_detected(
    bytes: &[u8],
    name: &str,
    non_finite: crate::NonFinite,
) -> Result<(PolygonSoup, Format), IoError> {
    let format = crate::sniff_format(bytes, name)?;
    Ok((
        crate::read_bytes_with(bytes, format, name, non_finite)?,
        format,
    ))
}

/// The whole of a stream (standard input) within `limits`, decompressed when it starts with the
/// gzip magic. `name`: the input's name in error messages.
///
/// # Errors
/// [`IoError::Io`] (read, corrupt gzip), [`IoError::InputTooLarge`], [`IoError::OutOfMemory`].
pub fn load_reader(
    mut reader: impl Read,
    limits: &ReadLimits,
    name: &str,
) -> Result<Vec<u8>, IoError> {
    let ctx = Ctx::new(name);
    let mut bytes = Vec::new();
    read_limited(&mut reader, limits.max_bytes, &mut bytes)
        .map_err(|e| e.into_error(ctx, limits))?;
    if crate::is_gzip(&bytes) {
        let raw = std::mem::take(&mut bytes);
        return decompress_gzip(&raw[..], limits, name);
    }
    Ok(bytes)
}

/// A path as error messages show it (control characters escaped).
fn path_name(path: &Path) -> String {
    surftopo_mesh::printable(&path.display().to_string()).into_owned()
}

/// The whole contents of a file within `limits`, decompressed when its name ends in `.gz`
/// (every gzip member, then trailing zero padding is ignored, as `gzip -d` does).
///
/// # Errors
/// [`IoError::Io`] (open, read, corrupt gzip), [`IoError::InputTooLarge`],
/// [`IoError::OutOfMemory`].
pub fn load_path(path: &Path, limits: &ReadLimits) -> Result<Vec<u8>, IoError> {
    let name = path_name(path);
    let ctx = Ctx::new(&name);
    let mut file = File::open(path).map_err(|e| ctx.io(e))?;
    let len = file.metadata().map(|m| m.len()).unwrap_or(0);
    let mut bytes = Vec::new();
    if is_gzip_path(path) {
        // The gzip trailer holds the uncompressed size mod 2^32: a capacity hint only, capped
        // at 32 times the compressed size and at the limit.
        if len >= 18 {
            let mut isize = [0u8; 4];
            file.seek(SeekFrom::End(-4))
                .and_then(|_| file.read_exact(&mut isize))
                .and_then(|()| file.rewind())
                .map_err(|e| ctx.io(e))?;
            let hint = u64::from(u32::from_le_bytes(isize))
                .min(len.saturating_mul(32))
                .min(limits.max_bytes);
            let _ = bytes.try_reserve_exact(usize::try_from(hint).unwrap_or(0));
        }
        gunzip_into(BufReader::with_capacity(1 << 16, file), limits, &mut bytes)
    } else {
        if len > limits.max_bytes {
            return Err(Load::TooLarge.into_error(ctx, limits));
        }
        let _ = bytes.try_reserve_exact(usize::try_from(len).unwrap_or(0));
        read_limited(&mut file, limits.max_bytes, &mut bytes)
    }
    .map_err(|e| e.into_error(ctx, limits))?;
    Ok(bytes)
}

/// Decompresses a whole gzip stream within `limits`: every member in turn, then trailing zero
/// bytes (tape or block padding, which `gzip -d` accepts) are ignored; anything else after a
/// member must be another member. Memory grows with the output actually produced, never with
/// what the stream's header or trailer claims. `name` is the file name used in errors.
///
/// # Errors
/// [`IoError::Io`] for a corrupt or truncated stream or non-zero trailing garbage,
/// [`IoError::InputTooLarge`], [`IoError::OutOfMemory`].
pub fn decompress_gzip(
    reader: impl BufRead,
    limits: &ReadLimits,
    name: &str,
) -> Result<Vec<u8>, IoError> {
    let mut bytes = Vec::new();
    gunzip_into(reader, limits, &mut bytes).map_err(|e| e.into_error(Ctx::new(name), limits))?;
    Ok(bytes)
}

/// Why loading stopped.
enum Load {
    Io(io::Error),
    TooLarge,
    OutOfMemory(u64),
}

impl From<io::Error> for Load {
    fn from(e: io::Error) -> Self {
        Load::Io(e)
    }
}

impl Load {
    fn into_error(self, ctx: Ctx<'_>, limits: &ReadLimits) -> IoError {
        match self {
            Load::Io(e) => ctx.io(e),
            Load::TooLarge => IoError::InputTooLarge {
                file: ctx.name.to_owned(),
                limit: limits.max_bytes,
            },
            Load::OutOfMemory(bytes) => IoError::OutOfMemory {
                file: ctx.name.to_owned(),
                bytes,
            },
        }
    }
}

fn gunzip_into(
    mut input: impl BufRead,
    limits: &ReadLimits,
    out: &mut Vec<u8>,
) -> Result<(), Load> {
    loop {
        read_limited(&mut GzDecoder::new(&mut input), limits.max_bytes, out)?;
        let rest = input.fill_buf()?;
        match rest.first() {
            None => return Ok(()),
            Some(0) => return skip_zero_padding(&mut input),
            Some(_) => {} // another member
        }
    }
}

/// Consumes the rest of `input`, which must be zero bytes.
fn skip_zero_padding(input: &mut impl BufRead) -> Result<(), Load> {
    loop {
        let rest = input.fill_buf()?;
        if rest.is_empty() {
            return Ok(());
        }
        if rest.iter().any(|&b| b != 0) {
            return Err(Load::Io(io::Error::new(
                io::ErrorKind::InvalidData,
                "trailing garbage after the gzip data (only zero padding is allowed)",
            )));
        }
        let n = rest.len();
        input.consume(n);
    }
}

/// Appends all of `reader` to `out`, growing it fallibly (`try_reserve`), and stops with
/// [`Load::TooLarge`] once `out` would exceed `limit` bytes. Capacity reserved beforehand (the
/// file's size) is filled first; a full buffer is grown (doubling) only once a probe read shows
/// there is more, so an input of exactly the reserved size costs no extra memory.
fn read_limited(reader: &mut impl Read, limit: u64, out: &mut Vec<u8>) -> Result<(), Load> {
    const CHUNK: usize = 1 << 16;
    let limit = usize::try_from(limit).unwrap_or(usize::MAX);
    let mut len = out.len();
    let result = loop {
        if len == out.len() {
            let reserved = out.capacity().min(limit.saturating_add(1));
            if reserved > len {
                out.resize(reserved, 0);
            } else {
                let mut probe = [0u8; 8192];
                let n = match reader.read(&mut probe) {
                    Ok(0) => break Ok(()),
                    Ok(n) => n,
                    Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                    Err(e) => break Err(Load::Io(e)),
                };
                // Double (at least one chunk), but never beyond limit + 1 bytes.
                let room = len
                    .max(CHUNK)
                    .min(limit.saturating_add(1).saturating_sub(len))
                    .max(n);
                if out.try_reserve(room).is_err() {
                    break Err(Load::OutOfMemory((len + room) as u64));
                }
                out.resize(len + room, 0);
                out[len..len + n].copy_from_slice(&probe[..n]);
                len += n;
                if len > limit {
                    break Err(Load::TooLarge);
                }
                continue;
            }
        }
        match reader.read(&mut out[len..]) {
            Ok(0) => break Ok(()),
            Ok(n) => {
                len += n;
                if len > limit {
                    break Err(Load::TooLarge);
                }
            }
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => break Err(Load::Io(e)),
        }
    };
    out.truncate(len);
    if result.is_err() {
        // What was read is dropped now, not when the caller gets round to it.
        *out = Vec::new();
    }
    result
}

/// Writes a mesh file atomically.
///
/// `path`: the target; its extension gives the format (`.obj`, `.off`,
/// `.ply`) and a trailing `.gz` compresses; `soup`: what to write (checked
/// first, see [`PolygonSoup::validate`]); `options`: PLY encoding (binary
/// little endian by default) and gzip level. The data goes to a temporary
/// file `.name.tmp-<pid>-<n>` in the same directory, which is then renamed
/// over `path` (see [`StagedFile`] on why it is not synced); on any error the
/// temporary file is removed and `path` is left as it was.
pub fn write_path(path: &Path, soup: &PolygonSoup, options: &WriteOptions) -> Result<(), IoError> {
    let staged = stage_path(path, soup, options)?;
    staged
        .commit()
        .map_err(|e| Ctx::new(&path_name(path)).io(e))
}

/// [`write_path`] up to the rename: the mesh file written under its temporary name,
/// to be renamed over `path` by [`StagedFile::commit`] (or removed when dropped), so that several
/// outputs are renamed only once all are written.
pub fn stage_path(
    path: &Path,
    soup: &PolygonSoup,
    options: &WriteOptions,
) -> Result<StagedFile, IoError> {
    let format = Format::from_path(path).ok_or_else(|| IoError::UnsupportedFormat {
        path: path_name(path),
    })?;
    stage_path_as(path, soup, format, is_gzip_path(path), options)
}

/// [`stage_path`] in `format`, gzip-compressed when `gzip`, whatever the name of `path` says.
///
/// # Errors
/// As [`stage_path`] (but never [`IoError::UnsupportedFormat`]).
pub fn stage_path_as(
    path: &Path,
    soup: &PolygonSoup,
    format: Format,
    gzip: bool,
    options: &WriteOptions,
) -> Result<StagedFile, IoError> {
    crate::check_writable(soup, format, options)?;
    stage_write(path, |file| encode(file, soup, format, gzip, options))
        .map_err(|e| Ctx::new(&path_name(path)).io(e))
}

/// [`crate::write()`], gzip-compressed (at `options.gzip_level`) when `gzip`: for a stream such as
/// standard output.
///
/// # Errors
/// As [`crate::write()`].
pub fn write_encoded(
    writer: impl Write,
    soup: &PolygonSoup,
    format: Format,
    gzip: bool,
    options: &WriteOptions,
) -> Result<(), IoError> {
    crate::check_writable(soup, format, options)?;
    encode(writer, soup, format, gzip, options)
        .map(drop)
        .map_err(|e| Ctx::new("<writer>").io(e))
}

/// Writes a checked soup, through gzip when `gzip`; returns the writer.
fn encode<W: Write>(
    writer: W,
    soup: &PolygonSoup,
    format: Format,
    gzip: bool,
    options: &WriteOptions,
) -> io::Result<W> {
    if gzip {
        let level = Compression::new(options.gzip_level.min(9));
        crate::write_unchecked(GzEncoder::new(writer, level), soup, format, options)?.finish()
    } else {
        crate::write_unchecked(writer, soup, format, options)
    }
}

/// Counter making temporary names unique within the process.
static TMP_COUNTER: AtomicU64 = AtomicU64::new(0);

/// The temporary files [`atomic_write`] has open, for [`remove_temporaries_then`].
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The most bytes of the target's name kept in a temporary name: with the dot and the
/// `.tmp-<pid>-<n>` suffix (at most 46 bytes) the name stays within the usual 255-byte limit
/// of a file name whenever the target's own name is legal.
const TMP_NAME_PREFIX: usize = 200;

/// Temporary sibling of `path`: `.name.tmp-<pid>-<n>`, `name` cut to its first 200 bytes (at a
/// character boundary) so that the temporary name is legal whenever the target's is.
fn temp_path(path: &Path) -> io::Result<PathBuf> {
    let file_name = path
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "path has no file name"))?;
    let mut tmp = OsString::from(".");
    match file_name.to_str() {
        Some(name) if name.len() > TMP_NAME_PREFIX => {
            let cut = (0..=TMP_NAME_PREFIX)
                .rev()
                .find(|&i| name.is_char_boundary(i))
                .unwrap_or(0);
            tmp.push(&name[..cut]);
        }
        Some(_) => tmp.push(file_name),
        // Not UTF-8: a lossy prefix is as good a temporary name.
        None => tmp.push(
            file_name
                .to_string_lossy()
                .chars()
                .scan(0usize, |bytes, c| {
                    *bytes += c.len_utf8();
                    (*bytes <= TMP_NAME_PREFIX).then_some(c)
                })
                .collect::<String>(),
        ),
    }
    tmp.push(format!(
        ".tmp-{}-{}",
        std::process::id(),
        TMP_COUNTER.fetch_add(1, Ordering::Relaxed)
    ));
    Ok(path.with_file_name(tmp))
}

fn temporaries() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    TEMPORARIES
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Removes every temporary file of an [`atomic_write`] still in progress, then runs `last`
/// (typically `std::process::exit`) while no write can rename its temporary file or start a new
/// one. For signal handlers (SIGINT, SIGTERM, SIGHUP): an interrupted write leaves neither a
/// temporary file nor a half-written target.
pub fn remove_temporaries_then<T>(last: impl FnOnce() -> T) -> T {
    let mut open = temporaries();
    for tmp in open.drain(..) {
        let _ = fs::remove_file(tmp);
    }
    last()
}

/// Runs `fill` on a new temporary file next to `path` and renames it over
/// `path` ([`StagedFile`]); removes the temporary file on any error. The temporary file is registered
/// for [`remove_temporaries_then`] while it exists.
pub fn atomic_write(path: &Path, fill: impl FnOnce(File) -> io::Result<File>) -> io::Result<()> {
    stage_write(path, fill)?.commit()
}

/// A file written under a temporary name beside its target, not yet renamed over it.
/// [`StagedFile::commit`] renames it; dropping it uncommitted removes the temporary file. While
/// it exists the temporary file is registered for [`remove_temporaries_then`], so a signal
/// between writing and renaming leaves nothing behind.
///
/// What this guarantees is atomicity against a failure of the process (an error, a signal, a
/// crash, a full disk): the target is either left as it was or replaced by the complete new
/// file, never half written, because the rename happens only once every byte has been handed to
/// the kernel, which keeps them whatever becomes of the process. Neither the file nor its folder
/// is synced (`fsync`): that would add durability against a crash of the operating system or a
/// power cut, at a cost of the order of the writing itself (the disk's write-back, waited for),
/// and surftopo's outputs are derived data that a rerun gives again. After such a crash a file
/// committed just before may therefore be missing or empty, as with most command-line tools
/// (compilers, `numpy.save`); callers that need more sync the target themselves.
#[derive(Debug)]
pub struct StagedFile {
    tmp: PathBuf,
    target: PathBuf,
    committed: bool,
}

/// Runs `fill` on a new temporary file next to `path` (keeping the permissions of a file `path`
/// replaces), not synced ([`StagedFile`]); the rename is [`StagedFile::commit`]. On any error the temporary file
/// is removed.
pub fn stage_write(
    path: &Path,
    fill: impl FnOnce(File) -> io::Result<File>,
) -> io::Result<StagedFile> {
    let tmp = temp_path(path)?;
    let file = {
        let mut open = temporaries();
        let file = OpenOptions::new().write(true).create_new(true).open(&tmp)?;
        open.push(tmp.clone());
        file
    };
    // From here on, dropping `staged` (an error) removes the temporary file.
    let staged = StagedFile {
        tmp,
        target: path.to_path_buf(),
        committed: false,
    };
    if let Ok(meta) = fs::metadata(path) {
        // Keep the permissions of the file being replaced.
        let _ = file.set_permissions(meta.permissions());
    }
    let mut file = fill(file)?;
    file.flush()?;
    Ok(staged)
}

impl StagedFile {
    /// The file this one replaces once committed.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Renames the temporary file over the target (not synced: see [`StagedFile`]).
    ///
    /// # Errors
    /// The rename's error; the temporary file is then removed and the target left as it was.
    pub fn commit(mut self) -> io::Result<()> {
        {
            let mut open = temporaries();
            fs::rename(&self.tmp, &self.target)?;
            open.retain(|p| p != &self.tmp);
            self.committed = true;
        }
        Ok(())
    }
}

impl Drop for StagedFile {
    fn drop(&mut self) {
        if !self.committed {
            let mut open = temporaries();
            let _ = fs::remove_file(&self.tmp);
            open.retain(|p| p != &self.tmp);
        }
    }
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
    fn a_staged_file_replaces_its_target_only_when_committed() {
        let dir = tempfile::tempdir().unwrap();
        let (kept, dropped) = (dir.path().join("a.obj"), dir.path().join("b.obj"));
        fs::write(&kept, b"old").unwrap();
        let write = |path: &Path| {
            stage_write(path, |mut f| {
                f.write_all(b"new")?;
                Ok(f)
            })
            .unwrap()
        };
        let (a, b) = (write(&kept), write(&dropped));
        assert_eq!(fs::read(&kept).unwrap(), b"old");
        assert_eq!(entries(dir.path()).len(), 3, "a.obj and two temporaries");
        assert_eq!(
            temporaries()
                .iter()
                .filter(|t| t.starts_with(dir.path()))
                .count(),
            2
        );
        a.commit().unwrap();
        drop(b);
        assert_eq!(fs::read(&kept).unwrap(), b"new");
        assert_eq!(entries(dir.path()), ["a.obj"]);
        assert_eq!(
            temporaries()
                .iter()
                .filter(|t| t.starts_with(dir.path()))
                .count(),
            0
        );
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

    #[test]
    fn temporary_names_stay_within_the_file_name_limit() {
        let dir = tempfile::tempdir().unwrap();
        for len in [5usize, 200, 201, 241, 250, 255] {
            let stem = "é".repeat((len - 4) / 2) + &"x".repeat((len - 4) % 2);
            let name = format!("{stem}.obj");
            assert_eq!(name.len(), len);
            let target = dir.path().join(&name);
            let tmp = temp_path(&target).unwrap();
            assert!(tmp.file_name().unwrap().len() <= 255, "{len}");
            atomic_write(&target, |mut f| {
                f.write_all(b"x")?;
                Ok(f)
            })
            .unwrap();
            assert_eq!(fs::read(&target).unwrap(), b"x");
            fs::remove_file(&target).unwrap();
        }
        assert!(entries(dir.path()).is_empty());
    }

    fn gz(data: &[u8]) -> Vec<u8> {
        let mut e = GzEncoder::new(Vec::new(), Compression::fast());
        e.write_all(data).unwrap();
        e.finish().unwrap()
    }

    #[test]
    fn gzip_members_padding_and_limits() {
        let limits = ReadLimits { max_bytes: 1000 };
        let two = [gz(b"ab"), gz(b"cd"), vec![0; 700]].concat();
        assert_eq!(decompress_gzip(&two[..], &limits, "x").unwrap(), b"abcd");
        let junk = [gz(b"ab"), b"\0\0x".to_vec()].concat();
        let e = decompress_gzip(&junk[..], &limits, "x").unwrap_err();
        assert!(e.to_string().contains("trailing garbage"), "{e}");
        // A bomb stops at the limit, whatever its trailer claims.
        let bomb = gz(&vec![0u8; 1 << 20]);
        let e = decompress_gzip(&bomb[..], &limits, "bomb.gz").unwrap_err();
        assert!(
            matches!(e, IoError::InputTooLarge { limit: 1000, .. }),
            "{e}"
        );
        assert!(decompress_gzip(&b""[..], &limits, "x").is_err());
        let exact = gz(&[7u8; 1000]);
        assert_eq!(
            decompress_gzip(&exact[..], &limits, "x").unwrap().len(),
            1000
        );
    }

    #[test]
    fn a_file_is_read_into_exactly_its_size() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("m.obj");
        fs::write(&path, vec![b'#'; 300_001]).unwrap();
        let bytes = load_path(&path, &ReadLimits::default()).unwrap();
        assert_eq!((bytes.len(), bytes.capacity()), (300_001, 300_001));
        let e = load_path(&path, &ReadLimits { max_bytes: 300_000 }).unwrap_err();
        assert!(matches!(e, IoError::InputTooLarge { .. }), "{e}");
    }
}
