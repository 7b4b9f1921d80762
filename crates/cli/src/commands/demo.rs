//! `surftopo demo`: every capability on built-in examples, needing no file.
//!
//! The examples are generated: a genus-2 brick with irregular connectivity (816
//! triangles, small enough for the brute force and the exact quality pairing to stay quick), a
//! Klein bottle and a torus with two holes (irreducible; the open torus also by `delaunay` and
//! `quad`), a pentagonal prism of polygons with a vertex in no face,
//! a small broken mesh for `info`'s problem classes, Dubois' flat tori T_x, T_{x+1} and
//! T_{x+1/3} (x = 10^9, exact corners), and a pillowcase sheared into needles (exact corners).
//! Each step calls the command's own code (its `run`, or the library functions it calls) and
//! prints one line: what was run, the result and its time.

use crate::args::{FormatArg, JsonArg, MeshJobArgs, SeedArg, WeldArg};
use crate::commands::{delaunay, generate, info, irreducible, isometric, quad};
use crate::output::{emit, format_seconds};
use std::path::{Path, PathBuf};
use std::time::Instant;
use surftopo_irreducible::Algorithm;
use surftopo_quad::{QuadAlgorithm, QualityObjective, QualityQuads};

/// The arguments of `demo`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Folder for the results (created if needed); by default a new folder in the system's
    /// temporary directory, kept and named in the summary.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// The parameter x of the flat tori T_x (Section 9 of the intrinsic-Delaunay paper): large
/// enough that flipping in double precision could not reach D_x.
const FLAT_TORUS_X: &str = "1000000000";
/// x + 1.
const FLAT_TORUS_X_PLUS_1: &str = "1000000001";
/// x + 1/3.
const FLAT_TORUS_X_PLUS_THIRD: &str = "3000000001/3";
/// The shear s of the needle pillowcase (the lattice `⟨(1, 0), (s, 1)⟩`): triangles of aspect
/// ratio about s².
const NEEDLE_SHEAR: &str = "1000";

/// Runs every capability on the built-in examples, writing the results into `--out` (or a new
/// temporary folder) and printing one line per step. A failing step (a full disk, an unwritable
/// folder) removes every file the run wrote, and the folder when the run created it: nothing is
/// left half done.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (dir, created) = match &args.out {
        Some(dir) => {
            let created = !dir.exists();
            std::fs::create_dir_all(dir).map_err(|e| crate::failure::unwritable(dir, &e))?;
            (dir.clone(), created)
        }
        None => (new_temporary_folder()?, true),
    };
    let demo = Demo {
        dir,
        written: std::cell::RefCell::default(),
    };
    let result = {
        // The commands' notes on stderr (polygons cut, vertices in no face) would break the
        // lines; each line says what they would.
        let _muted = crate::output::mute_notes();
        demo.steps()
    };
    if result.is_err() {
        demo.remove_written(created);
    }
    result
}

/// The demo's output folder and its steps.
struct Demo {
    dir: PathBuf,
    /// The files the steps write that did not exist before the run, in the order named.
    written: std::cell::RefCell<Vec<PathBuf>>,
}

impl Demo {
    /// Every step, one line each.
    fn steps(&self) -> anyhow::Result<()> {
        let started = Instant::now();
        emit(&format!(
            "surftopo demo: every capability on built-in examples; results in {}\n",
            crate::failure::shown(&self.dir)
        ))?;
        let input = self.generate_input()?;
        self.info(&input)?;
        self.convert(&input)?;
        self.irreducible(&input)?;
        self.other_surfaces()?;
        self.open_surface()?;
        self.quad(&input)?;
        self.exported()?;
        let tori = self.flat_tori()?;
        self.delaunay(&input, &tori)?;
        self.needle()?;
        self.isometric(&input, &tori)?;
        self.census()?;
        emit(&format!(
            "done in {}\n",
            format_seconds(started.elapsed().as_secs_f64())
        ))
    }

    /// After a failure: removes the files of [`Self::written`] (those that exist), then the
    /// folder if the run `created` it and it is empty.
    fn remove_written(&self, created: bool) {
        for path in self.written.borrow().iter() {
            let _ = std::fs::remove_file(path);
        }
        if created {
            let _ = std::fs::remove_dir(&self.dir);
        }
    }
}

/// The flat tori of the demo, as portalgon JSON files by exact corners.
struct FlatTori {
    /// T_x.
    x: PathBuf,
    /// T_{x+1}: isometric to T_x.
    x_plus_1: PathBuf,
    /// T_{x+1/3}: not isometric to T_x.
    x_plus_third: PathBuf,
}

impl Demo {
    /// The path of an output of the run; recorded for [`Self::remove_written`] unless a file
    /// of that name was there before the run.
    fn path(&self, name: &str) -> PathBuf {
        let path = self.dir.join(name);
        let mut written = self.written.borrow_mut();
        if !written.contains(&path) && !path.exists() {
            written.push(path.clone());
        }
        path
    }

    fn shown(&self, name: &str) -> String {
        crate::failure::shown(&self.path(name))
    }

    /// One line: the step, the result, the time.
    fn line(label: &str, result: &str, seconds: f64) -> anyhow::Result<()> {
        emit(&format!(
            "  {label:<34} {result} ({})\n",
            format_seconds(seconds)
        ))
    }

    /// The label of a step whose command prints its own line (with its time) after it.
    fn label(label: &str) -> anyhow::Result<()> {
        emit(&format!("  {label:<34} "))
    }

    /// `generate genus --genus 2 --size 2 --flips 1000 --seed 7`: the main input.
    fn generate_input(&self) -> anyhow::Result<PathBuf> {
        let input = self.path("input.obj");
        let start = Instant::now();
        let kind = generate::Kind::Genus { genus: 2, size: 2 };
        let surface = generate::modify(generate::generate(&kind)?, &modifiers(1000))?
            .into_plain()
            .ok_or_else(|| anyhow::anyhow!("the genus-2 brick is closed and orientable"))?;
        crate::output::write_surface(&input, &surface)?;
        let mesh = &surface.mesh;
        Self::line(
            "generate genus --genus 2 --flips 1000",
            &format!(
                "{}: a brick with 2 through-holes, 1000 random flips: {} vertices, {} edges, {} faces, genus {}",
                crate::failure::shown(&input),
                mesh.vertex_count(),
                mesh.edge_count(),
                mesh.face_count(),
                mesh.genus()
            ),
            start.elapsed().as_secs_f64(),
        )?;
        Ok(input)
    }

    /// `info` on the input, and on a small broken mesh with one problem of several classes.
    fn info(&self, input: &Path) -> anyhow::Result<()> {
        let start = Instant::now();
        let report = info::inspect_path(input, false)?;
        Self::line(
            "info",
            &format!(
                "{}: {} vertices, {} edges, {} faces, genus {}, closed {}, orientable {}, {} problems",
                crate::failure::shown(input),
                report.vertices,
                report.edges,
                report.faces,
                report.genus.map_or("-".to_string(), |g| g.to_string()),
                report.closed,
                report.orientable,
                report.problems_total
            ),
            start.elapsed().as_secs_f64(),
        )?;
        // A tetrahedron with a NaN coordinate, a zero-area face (vertices 1, 2, 3 on the x axis)
        // and a duplicate face: info lists them, every other command refuses the file.
        let broken = self.path("broken.obj");
        let text = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 0 1\nv nan 0 0\n\
                    f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\nf 1 2 4\n";
        std::fs::write(&broken, text).map_err(|e| crate::failure::unwritable(&broken, &e))?;
        let start = Instant::now();
        let report = info::inspect_path(&broken, false)?;
        let classes: Vec<String> = report
            .counts
            .0
            .entries()
            .iter()
            .filter(|&&(_, n)| n > 0)
            .map(|&(key, n)| format!("{n} {}", key.replace('_', " ")))
            .collect();
        Self::line(
            "info (a broken mesh)",
            &format!(
                "{}: {} problems: {}",
                crate::failure::shown(&broken),
                report.problems_total,
                classes.join(", ")
            ),
            start.elapsed().as_secs_f64(),
        )
    }

    /// `convert` to binary PLY and gzipped OFF, each read back and compared.
    fn convert(&self, input: &Path) -> anyhow::Result<()> {
        let (original, _) = crate::input::read_soup(input, false)?;
        for name in ["input.ply", "input.off.gz"] {
            let start = Instant::now();
            crate::output::write_soup(&self.path(name), &original)?;
            let (back, _) = crate::input::read_soup(&self.path(name), false)?;
            if back.positions != original.positions || back.face_indices != original.face_indices {
                return Err(anyhow::anyhow!(
                    "{}: read back differently from {}",
                    self.shown(name),
                    crate::failure::shown(input)
                ));
            }
            Self::line(
                &format!("convert input.obj {name}"),
                &format!(
                    "{}: {} vertices, {} faces, read back with the same positions (bit for bit) and faces",
                    self.shown(name),
                    back.positions.len(),
                    back.face_count()
                ),
                start.elapsed().as_secs_f64(),
            )?;
        }
        Ok(())
    }

    /// `irreducible` with each algorithm of the irreducible-triangulations paper.
    fn irreducible(&self, input: &Path) -> anyhow::Result<()> {
        let loaded = crate::input::load_surface(input, false)?;
        let pieces = surftopo_mesh::inspect(
            loaded.surface.mesh.vertex_slots(),
            &loaded.surface.to_triangles().1,
        )
        .surfaces;
        let surface = loaded.surface.clone().into();
        for algorithm in Algorithm::all(1) {
            let (reduced, report) = irreducible::reduce_covered(&surface, &pieces, algorithm)?;
            let name = format!("irreducible-{}.obj", algorithm.name());
            crate::output::write_soup(
                &self.path(&name),
                &irreducible::on_input_vertices(&loaded.soup, &reduced, false),
            )?;
            Self::line(
                &format!("irreducible --algorithm {}", algorithm.name()),
                &format!(
                    "{}: {} vertices, {} faces, {} (at most 26g - 4 = 48 vertices); {} contractions, {} link tests, {} edges tested twice",
                    self.shown(&name),
                    report.output.vertices,
                    report.output.faces,
                    report.output.names(),
                    report.contractions,
                    report.link_tests,
                    report.edges_tested_more_than_once
                ),
                report.seconds,
            )?;
        }
        Ok(())
    }

    /// A Klein bottle and a torus with two holes, each generated, classified by `info` and
    /// reduced by RS: irreducible triangulations beyond closed orientable surfaces.
    fn other_surfaces(&self) -> anyhow::Result<()> {
        let cases = [
            (
                "klein-bottle + irreducible",
                "klein-bottle.obj",
                generate::Kind::KleinBottle { m: 12, n: 6 },
                generate::Modifiers {
                    splits: 200,
                    ..modifiers(0)
                },
            ),
            (
                "torus --cut-holes 2 + irreducible",
                "open-torus.obj",
                generate::Kind::Torus { m: 24, n: 12 },
                generate::Modifiers {
                    cut_holes: 2,
                    ..modifiers(300)
                },
            ),
        ];
        for (label, name, kind, modifiers) in cases {
            let start = Instant::now();
            let surface = generate::modify(generate::generate(&kind)?, &modifiers)?;
            let (positions, triangles) = surface.to_triangles();
            let path = self.path(name);
            crate::output::write_soup(
                &path,
                &surftopo_io::PolygonSoup::from_triangles(positions, &triangles),
            )?;
            let pieces = surftopo_mesh::inspect(surface.positions.len(), &triangles).surfaces;
            let (reduced, report) =
                irreducible::reduce_covered(&surface, &pieces, Algorithm::RamaswamiSiqueira)?;
            let reduced_name = name.replace(".obj", "-irreducible.obj");
            crate::output::write_soup(
                &self.path(&reduced_name),
                &surftopo_io::PolygonSoup::from_triangles(surface.positions.clone(), &reduced),
            )?;
            Self::line(
                label,
                &format!(
                    "{}: {}, {} vertices; irreducible {}: {} vertices, {} contractions",
                    self.shown(name),
                    report.input.names(),
                    report.input.vertices,
                    self.shown(&reduced_name),
                    report.output.vertices,
                    report.contractions
                ),
                start.elapsed().as_secs_f64(),
            )?;
        }
        Ok(())
    }

    /// `quad` with each algorithm of the quadrangulation paper, Karp–Sipser, and both quality
    /// objectives.
    fn quad(&self, input: &Path) -> anyhow::Result<()> {
        let loaded = crate::input::load_surface(input, false)?;
        let (surface, input_vertices) = (&loaded.surface, loaded.report.input_vertices());
        let fail =
            |e: surftopo_quad::QuadError| anyhow::anyhow!("{}: {e}", self.shown("input.obj"));
        let mut runs: Vec<(String, QualityQuads)> = Vec::new();
        for algorithm in QuadAlgorithm::all(1) {
            let quads = surftopo_quad::quadrangulate_with_quality(
                &surface.mesh,
                &surface.positions,
                algorithm,
            )
            .map_err(fail)?;
            runs.push((format!("--algorithm {}", algorithm.name()), quads));
        }
        for objective in QualityObjective::ALL {
            let quads = surftopo_quad::quadrangulate_by_quality(
                &surface.mesh,
                &surface.positions,
                objective,
            )
            .map_err(fail)?;
            runs.push((format!("--objective {}", objective.name()), quads));
        }
        for (how, q) in &runs {
            let name = format!("quads-{}.obj", q.result.stats.algorithm);
            crate::output::write_soup(
                &self.path(&name),
                &crate::commands::quad::quad_soup(&loaded.soup, &input_vertices, &q.result),
            )?;
            let stats = &q.result.stats;
            Self::line(
                &format!("quad {how}"),
                &format!(
                    "{}: {} quads; initial pairing {:.1}%, {} flipped edges; cost {:.3}, quality median {:.3}",
                    self.shown(&name),
                    q.result.quads.len(),
                    stats.paired_percent,
                    stats.flipped_edges,
                    q.cost,
                    q.report.median
                ),
                stats.total_seconds,
            )?;
        }
        Ok(())
    }

    /// `generate flat-torus` for T_x, T_{x+1} and T_{x+1/3}, by exact corners.
    fn flat_tori(&self) -> anyhow::Result<FlatTori> {
        let tori = FlatTori {
            x: self.path("tx.json"),
            x_plus_1: self.path("tx-plus-1.json"),
            x_plus_third: self.path("tx-plus-third.json"),
        };
        let start = Instant::now();
        for (value, path) in [
            (FLAT_TORUS_X, &tori.x),
            (FLAT_TORUS_X_PLUS_1, &tori.x_plus_1),
            (FLAT_TORUS_X_PLUS_THIRD, &tori.x_plus_third),
        ] {
            let x: surftopo_intrinsic::geometry::Rational = value.parse()?;
            let exact = surftopo_intrinsic::generators::flat_torus_portalgon(&x, 1)?;
            crate::output::write_file(path, |w| {
                Ok(surftopo_intrinsic::PortalgonDoc::from_portalgon(&exact).write(w, false)?)
            })?;
        }
        Self::line(
            "generate flat-torus --x X",
            &format!(
                "{}, {}, {}: T_x, T_{{x+1}}, T_{{x+1/3}} for x = {FLAT_TORUS_X} (Section 9 of the intrinsic-Delaunay paper), 1 vertex, 2 triangles, exact corners",
                crate::failure::shown(&tori.x),
                crate::failure::shown(&tori.x_plus_1),
                crate::failure::shown(&tori.x_plus_third)
            ),
            start.elapsed().as_secs_f64(),
        )?;
        Ok(tori)
    }

    /// `delaunay` with each method, writing the Laplacian, the mass matrix, the tessellation and
    /// Dubois' reduced triangulation.
    fn delaunay(&self, input: &Path, tori: &FlatTori) -> anyhow::Result<()> {
        use delaunay::Method;
        let runs: [(&str, &Path, Method, bool, [&str; 5]); 5] = [
            (
                "delaunay --method flip",
                input,
                Method::Flip,
                false,
                [
                    "delaunay-flip.json",
                    "tessellation-flip.json",
                    "laplacian.mtx",
                    "mass.mtx",
                    "",
                ],
            ),
            (
                "delaunay --method voronoi",
                input,
                Method::Voronoi,
                false,
                [
                    "delaunay-voronoi.json",
                    "tessellation-voronoi.json",
                    "",
                    "",
                    "",
                ],
            ),
            (
                "delaunay --method dubois --exact",
                &tori.x,
                Method::Dubois,
                true,
                ["dx.json", "dx-tessellation.json", "", "", "dx-reduced.json"],
            ),
            (
                "delaunay --method auto --exact",
                &tori.x,
                Method::Auto,
                true,
                ["dx-auto.json", "", "dx-laplacian.mtx", "dx-mass.mtx", ""],
            ),
            (
                "delaunay --method auto",
                input,
                Method::Auto,
                false,
                ["delaunay-auto.json", "", "", "", ""],
            ),
        ];
        for (label, source, method, exact, [out, tessellation, laplacian, mass, reduced]) in runs {
            let file = |name: &str| (!name.is_empty()).then(|| self.path(name));
            let written: Vec<&str> = [
                ("-o", out),
                ("--tessellation", tessellation),
                ("--laplacian", laplacian),
                ("--mass", mass),
                ("--reduced", reduced),
            ]
            .into_iter()
            .filter(|(_, name)| !name.is_empty())
            .map(|(option, _)| option)
            .collect();
            Self::label(label)?;
            emit(&format!("[{}] ", written.join(" ")))?;
            delaunay::run(&delaunay::Args {
                output: file(out),
                tessellation: file(tessellation),
                laplacian: file(laplacian),
                mass: file(mass),
                reduced: file(reduced),
                ..delaunay_args(source, method, exact)
            })?;
        }
        Ok(())
    }

    /// A mesh as modellers export them: a pentagonal prism (two pentagons, five quads) whose
    /// vertex list has a vertex in no face; `delaunay` cuts the polygons into triangles and
    /// writes the Laplacian on the file's vertex numbering (an empty row for the loose vertex).
    fn exported(&self) -> anyhow::Result<()> {
        let path = self.path("prism.obj");
        let mut text = String::from("v 0 0 5\n");
        for z in [0.0, 1.0] {
            for k in 0..5 {
                let t = std::f64::consts::TAU * f64::from(k) / 5.0;
                text += &format!("v {} {} {z}\n", t.cos(), t.sin());
            }
        }
        text += "f 6 5 4 3 2\nf 7 8 9 10 11\n";
        for k in 0..5 {
            let (a, b) = (k + 2, (k + 1) % 5 + 2);
            text += &format!("f {a} {b} {} {}\n", b + 5, a + 5);
        }
        std::fs::write(&path, text).map_err(|e| crate::failure::unwritable(&path, &e))?;
        let (soup, _) = crate::input::read_soup(&path, false)?;
        let (cut, _) = crate::input::cut_polygons(&soup);
        Self::label("delaunay (polygons, a loose vertex)")?;
        emit(&format!(
            "[{} polygons cut into {} triangles; --laplacian: {} rows, row 0 empty] ",
            cut.polygons,
            cut.triangles.len(),
            soup.vertex_count()
        ))?;
        delaunay::run(&delaunay::Args {
            laplacian: Some(self.path("prism-laplacian.mtx")),
            ..delaunay_args(&path, delaunay::Method::Flip, false)
        })
    }

    /// A surface with boundary (the torus with two holes of [`Self::other_surfaces`]):
    /// `delaunay`'s Laplacian and mass matrix (the natural boundary condition), and `quad`'s
    /// maximum pairing (the fewest triangles left, proven by its certificate).
    fn open_surface(&self) -> anyhow::Result<()> {
        let input = self.path("open-torus.obj");
        Self::label("delaunay (torus with 2 holes)")?;
        emit("[--laplacian --mass, natural boundary condition] ")?;
        delaunay::run(&delaunay::Args {
            laplacian: Some(self.path("open-laplacian.mtx")),
            mass: Some(self.path("open-mass.mtx")),
            ..delaunay_args(&input, delaunay::Method::Flip, false)
        })?;
        Self::label("quad (torus with 2 holes)")?;
        quad::run(&quad::Args {
            job: MeshJobArgs {
                mesh: input,
                output: self.path("open-quads.obj"),
                format: FormatArg { format: None },
                seed: SeedArg { seed: 1 },
                json: JsonArg { json: false },
                weld: WeldArg { weld: false },
            },
            algorithm: surftopo_quad::QuadAlgorithm::KarpSipser.name().to_string(),
            objective: "count".to_string(),
            all_quads: false,
        })
    }

    /// Dubois' Theorem 1 on needles: the pillowcase of the lattice `⟨(1, 0), (s, 1)⟩`
    /// (`surftopo_intrinsic::generators::pillowcase`: a sphere with four cone points of angle π,
    /// its four triangles needles of aspect ratio about s²), by exact corners; its Delaunay
    /// tessellation is two unit squares by construction. At s = 1000, flipping in double
    /// precision ends with lengths off by about 1e-7 (`results/dubois_bench.md`), so the exact
    /// answer takes Theorem 1.
    fn needle(&self) -> anyhow::Result<()> {
        use surftopo_intrinsic::geometry::Rational;
        let path = self.path("needle.json");
        let number = |text: &str| text.parse::<Rational>();
        let (zero, one, shear) = (number("0")?, number("1")?, number(NEEDLE_SHEAR)?);
        let pillow =
            surftopo_intrinsic::generators::pillowcase(&[one.clone(), zero], &[shear, one])?;
        crate::output::write_file(&path, |w| {
            Ok(surftopo_intrinsic::PortalgonDoc::from_portalgon(&pillow).write(w, false)?)
        })?;
        Self::label("delaunay --method dubois --exact (needles)")?;
        emit(&format!(
            "[{}: a pillowcase sheared by s = {NEEDLE_SHEAR}, 4 cone points, aspect ratio \
             about s^2; --tessellation] ",
            crate::failure::shown(&path)
        ))?;
        delaunay::run(&delaunay::Args {
            tessellation: Some(self.path("needle-tessellation.json")),
            ..delaunay_args(&path, delaunay::Method::Dubois, true)
        })
    }

    /// `isometric` on an isometric and a non-isometric pair of flat tori (exact, Dubois'
    /// Theorem 1), and on the input against its intrinsic Delaunay triangulation (flipping).
    fn isometric(&self, input: &Path, tori: &FlatTori) -> anyhow::Result<()> {
        use delaunay::Method;
        let delaunay = self.path("delaunay-flip.json");
        let pairs: [(&str, &Path, &Path, Method, bool); 3] = [
            (
                "T_x, T_{x+1}",
                &tori.x,
                &tori.x_plus_1,
                Method::Dubois,
                true,
            ),
            (
                "T_x, T_{x+1/3}",
                &tori.x,
                &tori.x_plus_third,
                Method::Dubois,
                true,
            ),
            (
                "input.obj, delaunay-flip.json",
                input,
                &delaunay,
                Method::Flip,
                false,
            ),
        ];
        for (what, a, b, method, exact) in pairs {
            let start = Instant::now();
            let decision = isometric::decide_args(&isometric::Args {
                a: a.to_path_buf(),
                b: b.to_path_buf(),
                weld: crate::args::WeldArg { weld: false },
                method: delaunay::MethodOptions {
                    method,
                    exact,
                    faithful: false,
                },
                tolerance: surftopo_intrinsic::geometry::Tolerances::DEFAULT.isometry_length,
                json: crate::args::JsonArg { json: false },
            })?;
            let method = crate::args::value_name(&method);
            Self::line(
                &format!(
                    "isometric --method {method}{}",
                    if exact { " --exact" } else { "" }
                ),
                &format!("{what}: {decision}"),
                start.elapsed().as_secs_f64(),
            )?;
        }
        Ok(())
    }
}

impl Demo {
    /// `census torus` (the 21 irreducible triangulations of the torus, in Lutz's format), and
    /// `isomorphic` on the input and its PLY conversion.
    fn census(&self) -> anyhow::Result<()> {
        let start = Instant::now();
        let path = self.path("census-torus.txt");
        let census = surftopo_census::census(
            surftopo_census::SurfaceKind::orientable(1),
            surftopo_census::CensusOptions::default(),
        )
        .map_err(|e| crate::failure::invalid(e.to_string()))?;
        let text = surftopo_census::to_lutz(&census.triangulations);
        crate::output::write_file(&path, |w| {
            use std::io::Write;
            w.write_all(text.as_bytes())?;
            Ok(())
        })?;
        Self::line(
            "census torus",
            &format!(
                "{} irreducible triangulations, 7 to 10 vertices -> census-torus.txt",
                census.triangulations.len()
            ),
            start.elapsed().as_secs_f64(),
        )?;
        let start = Instant::now();
        let (isomorphic, _, _) =
            crate::commands::isomorphic::decide(&self.path("input.obj"), &self.path("input.ply"))?;
        Self::line(
            "isomorphic input.obj input.ply",
            if isomorphic {
                "isomorphic"
            } else {
                "not isomorphic"
            },
            start.elapsed().as_secs_f64(),
        )
    }
}

/// A new folder `surftopo-demo-<pid>[-k]` in the system's temporary directory (created, never
/// one that exists already).
fn new_temporary_folder() -> anyhow::Result<PathBuf> {
    let base = std::env::temp_dir().join(format!("surftopo-demo-{}", std::process::id()));
    let mut k = 0u32;
    loop {
        let dir = if k == 0 {
            base.clone()
        } else {
            PathBuf::from(format!("{}-{k}", base.display()))
        };
        match std::fs::create_dir(&dir) {
            Ok(()) => return Ok(dir),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && k < 1000 => k += 1,
            Err(e) => return Err(crate::failure::unwritable(&dir, &e)),
        }
    }
}

/// The arguments of `delaunay` on `input` by `method` (exactly when `exact`), writing nothing.
fn delaunay_args(input: &Path, method: delaunay::Method, exact: bool) -> delaunay::Args {
    delaunay::Args {
        input: input.to_path_buf(),
        output: None,
        tessellation: None,
        laplacian: None,
        mass: None,
        max_flips: None,
        mollify: None,
        tufted: false,
        weld: WeldArg { weld: false },
        json: JsonArg { json: false },
        reduced: None,
        method: delaunay::MethodOptions {
            method,
            exact,
            faithful: false,
        },
    }
}

/// The modifiers of `generate`: `flips` random flips, seed 7.
fn modifiers(flips: usize) -> generate::Modifiers {
    generate::Modifiers {
        output: None,
        format: None,
        subdivide: 0,
        simplify: None,
        flips,
        splits: 0,
        cut_holes: 0,
        copies: 1,
        shuffle_faces: false,
        seed: 7,
    }
}
