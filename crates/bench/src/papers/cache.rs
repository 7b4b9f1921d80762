//! The cache of generated inputs (`target/papers-cache/`): the bricks and their simplifications
//! take minutes at the papers' sizes (a genus-3,500 chain simplified down to 47k triangles most),
//! far longer than the algorithms measured on them.
//!
//! An input is named by its recipe ([`Recipe::key`]: the generator, its parameters, each
//! simplification's target and seed, and [`CACHE_VERSION`]), stored in a file named after the
//! recipe's FNV-1a hash that repeats the recipe in its header (a different recipe under the same
//! hash is a miss). The file holds the dense positions and triangles of
//! [`surftopo_mesh::Surface::to_triangles`]; loading rebuilds the surface with
//! [`surftopo_mesh::Surface::from_triangles`]. Decision: a built input is put through that same
//! round trip ([`canonical`]) before it is measured or simplified further, so an input read from
//! the cache and one built afresh are the same surface, ids included, and the run's figures do
//! not depend on the cache. Files are written to a temporary name and renamed (a run stopped
//! midway leaves no half-written entry); an unreadable or inconsistent entry is a miss and is
//! rebuilt.

use std::cell::Cell;
use std::io::{BufReader, BufWriter, Read, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

use surftopo_mesh::Surface;
use surftopo_mesh::generators::{CavityBox, simplify};

/// Bump when a generator (bricks, simplification) or the file layout changes: every entry made
/// before is then a miss.
pub const CACHE_VERSION: u32 = 1;

const MAGIC: &[u8] = b"surftopo papers input\n";

/// How an input is built: a brick, then simplifications, each to a triangle count with a seed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Recipe {
    /// Cavities, holes and target triangles of [`CavityBox::fit`].
    pub brick: (u32, u32, u64),
    /// Successive simplifications ([`simplify`]): (target faces, seed).
    pub simplifications: Vec<(usize, u64)>,
}

impl Recipe {
    /// The brick with `cavities`, `holes` and about `triangles` triangles.
    pub fn brick(cavities: u32, holes: u32, triangles: u64) -> Self {
        Self {
            brick: (cavities, holes, triangles),
            simplifications: Vec::new(),
        }
    }

    /// This recipe followed by a simplification to `target_faces` with `seed`.
    pub fn simplified(&self, target_faces: usize, seed: u64) -> Self {
        let mut next = self.clone();
        next.simplifications.push((target_faces, seed));
        next
    }

    /// The recipe as text, the cache key.
    pub fn key(&self) -> String {
        let (c, h, t) = self.brick;
        let mut key = format!("v{CACHE_VERSION} brick {c} cavities {h} holes {t} triangles");
        for (target, seed) in &self.simplifications {
            key += &format!(" | simplify to {target} seed {seed}");
        }
        key
    }

    fn parent(&self) -> Option<Self> {
        let mut parent = self.clone();
        parent.simplifications.pop().map(|_| parent)
    }
}

/// The surface rebuilt from its dense triangles: what loading a cache entry gives.
pub fn canonical(surface: &Surface) -> Surface {
    let (positions, triangles) = surface.to_triangles();
    Surface::from_triangles(positions, &triangles).expect("a valid surface rebuilds")
}

/// Where inputs are cached (`None`: nothing is read or written), and what the run did with it.
pub struct Cache {
    dir: Option<PathBuf>,
    last: std::cell::RefCell<Option<(String, Surface)>>,
    built: Cell<(u32, f64)>,
    loaded: Cell<(u32, f64)>,
}

impl Cache {
    /// A cache in `dir`, or none.
    pub fn new(dir: Option<PathBuf>) -> Self {
        Self {
            dir,
            last: std::cell::RefCell::new(None),
            built: Cell::new((0, 0.0)),
            loaded: Cell::new((0, 0.0)),
        }
    }

    /// The default folder: `target/papers-cache` in the workspace.
    pub fn default_dir() -> PathBuf {
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../target/papers-cache")
    }

    /// The input of `recipe`: the last one made (a chain asks for its previous input again), or
    /// read from the cache, or built (from its parent recipe, itself got the same way) and
    /// stored.
    pub fn get(&self, recipe: &Recipe) -> Surface {
        let key = recipe.key();
        if let Some((k, s)) = &*self.last.borrow()
            && *k == key
        {
            return s.clone();
        }
        let start = Instant::now();
        let surface = match self.read(&key) {
            Some(s) => {
                let (n, t) = self.loaded.get();
                self.loaded.set((n + 1, t + start.elapsed().as_secs_f64()));
                s
            }
            None => {
                let surface = match recipe.parent() {
                    None => {
                        let (c, h, t) = recipe.brick;
                        canonical(&CavityBox::fit(c, h, t).generate())
                    }
                    Some(parent) => {
                        let (target, seed) = *recipe.simplifications.last().expect("a step");
                        let parent = self.get(&parent);
                        let start = Instant::now();
                        let s = canonical(&simplify(&parent, target, seed));
                        self.add_built(start);
                        self.write(&key, &s);
                        *self.last.borrow_mut() = Some((key, s.clone()));
                        return s;
                    }
                };
                self.add_built(start);
                self.write(&key, &surface);
                surface
            }
        };
        *self.last.borrow_mut() = Some((key, surface.clone()));
        surface
    }

    fn add_built(&self, start: Instant) {
        let (n, t) = self.built.get();
        self.built.set((n + 1, t + start.elapsed().as_secs_f64()));
    }

    /// Inputs built and their seconds, inputs read from the cache and their seconds.
    pub fn counts(&self) -> ((u32, f64), (u32, f64)) {
        (self.built.get(), self.loaded.get())
    }

    fn path(&self, key: &str) -> Option<PathBuf> {
        let hash = key.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
        });
        self.dir
            .as_ref()
            .map(|d| d.join(format!("{hash:016x}.bin")))
    }

    fn read(&self, key: &str) -> Option<Surface> {
        let path = self.path(key)?;
        let file = std::fs::File::open(&path).ok()?;
        match read_entry(&mut BufReader::new(file), key) {
            Ok(s) => Some(s),
            Err(e) => {
                eprintln!("papers cache: {}: {e}; rebuilt", path.display());
                None
            }
        }
    }

    fn write(&self, key: &str, surface: &Surface) {
        let Some(path) = self.path(key) else { return };
        if let Err(e) = write_entry(&path, key, surface) {
            eprintln!("papers cache: {}: not written: {e}", path.display());
        }
    }
}

fn read_entry(r: &mut impl Read, key: &str) -> std::io::Result<Surface> {
    let bad = |what: &str| std::io::Error::new(std::io::ErrorKind::InvalidData, what.to_string());
    let mut magic = vec![0; MAGIC.len()];
    r.read_exact(&mut magic)?;
    if magic != MAGIC {
        return Err(bad("not a cache entry"));
    }
    let mut word = [0u8; 8];
    let mut u64_at = |r: &mut dyn Read| -> std::io::Result<u64> {
        r.read_exact(&mut word)?;
        Ok(u64::from_le_bytes(word))
    };
    let key_len = u64_at(r)? as usize;
    if key_len != key.len() {
        return Err(bad("another recipe"));
    }
    let mut stored = vec![0; key_len];
    r.read_exact(&mut stored)?;
    if stored != key.as_bytes() {
        return Err(bad("another recipe"));
    }
    let (vertices, faces) = (u64_at(r)? as usize, u64_at(r)? as usize);
    let mut bytes = vec![0u8; vertices * 24];
    r.read_exact(&mut bytes)?;
    let positions = bytes
        .chunks_exact(24)
        .map(|c| [0, 8, 16].map(|i| f64::from_le_bytes(c[i..i + 8].try_into().expect("8"))))
        .collect();
    let mut bytes = vec![0u8; faces * 12];
    r.read_exact(&mut bytes)?;
    let triangles: Vec<[u32; 3]> = bytes
        .chunks_exact(12)
        .map(|c| [0, 4, 8].map(|i| u32::from_le_bytes(c[i..i + 4].try_into().expect("4"))))
        .collect();
    if r.read(&mut [0u8; 1])? != 0 {
        return Err(bad("trailing bytes"));
    }
    Surface::from_triangles(positions, &triangles).map_err(|e| bad(&e.to_string()))
}

fn write_entry(path: &Path, key: &str, surface: &Surface) -> std::io::Result<()> {
    let dir = path.parent().expect("a file in the cache folder");
    std::fs::create_dir_all(dir)?;
    let (positions, triangles) = surface.to_triangles();
    let mut tmp = tempfile::NamedTempFile::new_in(dir)?;
    {
        let mut w = BufWriter::new(tmp.as_file_mut());
        w.write_all(MAGIC)?;
        w.write_all(&(key.len() as u64).to_le_bytes())?;
        w.write_all(key.as_bytes())?;
        w.write_all(&(positions.len() as u64).to_le_bytes())?;
        w.write_all(&(triangles.len() as u64).to_le_bytes())?;
        for p in &positions {
            for x in p {
                w.write_all(&x.to_le_bytes())?;
            }
        }
        for t in &triangles {
            for i in t {
                w.write_all(&i.to_le_bytes())?;
            }
        }
        w.flush()?;
    }
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cached_chain_is_the_chain_built_afresh() {
        let dir = tempfile::tempdir().expect("temp dir");
        let recipe = Recipe::brick(3, 1, 2_000)
            .simplified(1_200, 1)
            .simplified(700, 1);
        let fresh = Cache::new(None).get(&recipe);
        assert!(fresh.mesh.face_count() <= 700 && fresh.mesh.genus() == 1);
        let writing = Cache::new(Some(dir.path().to_path_buf()));
        assert_eq!(writing.get(&recipe), fresh);
        assert_eq!(
            writing.counts().0.0,
            3,
            "brick and two simplifications built"
        );
        let reading = Cache::new(Some(dir.path().to_path_buf()));
        assert_eq!(reading.get(&recipe), fresh);
        assert_eq!(reading.counts().0.0, 0, "nothing built");
        assert_eq!(reading.counts().1.0, 1, "only the asked input read");
        // Another recipe hashed to the same file name is a miss, and so is a damaged entry.
        let path = reading.path(&recipe.key()).expect("a path");
        let other = recipe.simplified(600, 2);
        std::fs::copy(&path, reading.path(&other.key()).unwrap()).unwrap();
        let again = Cache::new(Some(dir.path().to_path_buf()));
        assert_eq!(again.get(&other), Cache::new(None).get(&other));
        assert_eq!(again.counts().0.0, 1, "the other recipe built");
        let bytes = std::fs::read(&path).unwrap();
        std::fs::write(&path, &bytes[..bytes.len() - 5]).unwrap();
        let damaged = Cache::new(Some(dir.path().to_path_buf()));
        assert_eq!(damaged.get(&recipe), fresh);
        assert_eq!(damaged.counts().0.0, 1, "the damaged entry rebuilt");
    }
}
