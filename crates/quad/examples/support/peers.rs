//! The Python peer harness (`crates/quad/peer/quad_peers.py`: Gmsh's Blossom recombination,
//! Blender's join_triangles) run on an OFF file, its output read back.

use std::error::Error;
use std::path::Path;
use std::process::Command;

/// The vertices and faces of an OFF file written by the harness.
pub type Polygons = (Vec<[f64; 3]>, Vec<Vec<usize>>);

/// What a peer made: its output (its own vertices after the call, the quads and the triangles
/// left) and the (wall, process CPU) seconds of the conversion call alone.
pub struct PeerOutput {
    pub positions: Vec<[f64; 3]>,
    pub faces: Vec<Vec<usize>>,
    pub seconds: f64,
    pub cpu_seconds: f64,
}

impl PeerOutput {
    /// The quads (faces of four corners).
    pub fn quads(&self) -> Vec<[usize; 4]> {
        self.faces
            .iter()
            .filter(|f| f.len() == 4)
            .map(|f| [f[0], f[1], f[2], f[3]])
            .collect()
    }

    /// The triangles left.
    pub fn triangles_left(&self) -> usize {
        self.faces.iter().filter(|f| f.len() == 3).count()
    }
}

/// Reads an OFF file of polygons.
pub fn read_off(path: &Path) -> Result<Polygons, Box<dyn Error>> {
    let text = std::fs::read_to_string(path)?;
    let mut words = text.split_whitespace();
    if words.next() != Some("OFF") {
        return Err(format!("{}: not OFF", path.display()).into());
    }
    let vertices: usize = words.next().ok_or("no vertex count")?.parse()?;
    let faces: usize = words.next().ok_or("no face count")?.parse()?;
    words.next();
    let mut positions = Vec::with_capacity(vertices);
    for _ in 0..vertices {
        let mut p = [0.0; 3];
        for c in &mut p {
            *c = words.next().ok_or("truncated vertex")?.parse()?;
        }
        positions.push(p);
    }
    let mut out = Vec::with_capacity(faces);
    for _ in 0..faces {
        let k: usize = words.next().ok_or("truncated face")?.parse()?;
        let face = (0..k)
            .map(|_| Ok(words.next().ok_or("truncated face")?.parse::<usize>()?))
            .collect::<Result<Vec<_>, Box<dyn Error>>>()?;
        if face.iter().any(|&v| v >= vertices) {
            return Err(format!("{}: face {face:?} out of range", path.display()).into());
        }
        out.push(face);
    }
    Ok((positions, out))
}

/// Runs `quad_peers.py TOOL INPUT OUTPUT` (`tool`: `gmsh`, `gmsh-blossom` or `blender`) with
/// `python` and reads its output back (the output file is removed).
pub fn run_peer(python: &Path, tool: &str, input: &Path) -> Result<PeerOutput, Box<dyn Error>> {
    let harness = Path::new(env!("CARGO_MANIFEST_DIR")).join("peer/quad_peers.py");
    let output = input.with_extension(format!("{tool}.off"));
    let run = Command::new(python)
        .arg(&harness)
        .arg(tool)
        .arg(input)
        .arg(&output)
        .output()?;
    if !run.status.success() {
        return Err(format!("{tool}: {}", String::from_utf8_lossy(&run.stderr)).into());
    }
    let stdout = String::from_utf8_lossy(&run.stdout);
    let line = stdout
        .lines()
        .rfind(|l| l.starts_with('{'))
        .ok_or("no timing line")?;
    let v: serde_json::Value = serde_json::from_str(line)?;
    let seconds = v["seconds"].as_f64().ok_or("no seconds")?;
    let cpu_seconds = v["cpu_seconds"].as_f64().ok_or("no cpu_seconds")?;
    let (positions, faces) = read_off(&output)?;
    std::fs::remove_file(&output)?;
    Ok(PeerOutput {
        positions,
        faces,
        seconds,
        cpu_seconds,
    })
}

/// The version of a peer's Python module (`expr` printed after `import module`), or `?`.
pub fn peer_version(python: &Path, module: &str, expr: &str) -> String {
    Command::new(python)
        .arg("-c")
        .arg(format!("import {module}; print({expr})"))
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_else(|| "?".into())
}
