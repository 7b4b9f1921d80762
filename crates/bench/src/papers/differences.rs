//! The "Where we differ from the paper" section of each report: for each disagreement, what was
//! measured (figures taken from this run's rows) and what causes it, or "not yet explained".

use std::fmt::Write as _;

use super::inputs::Scale;
use super::numbers::{self, value};
use super::records::{IntrinsicRecord, IrreducibleRow as Row, QuadRecord, ratios};
use super::report::number;

fn range(values: &[f64]) -> String {
    if values.is_empty() {
        return "not run".into();
    }
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    format!("{lo:.2}–{hi:.2}")
}

fn group_ratio(rows: &[Row], group: &str, k: usize) -> Vec<f64> {
    rows.iter()
        .filter(|r| r.group == group)
        .map(|r| ratios(r)[k])
        .filter(|x| x.is_finite())
        .collect()
}

fn paper_ratio(group: &str, k: usize) -> Vec<f64> {
    numbers::IRREDUCIBLE_RATIOS
        .iter()
        .filter(|r| r.0.starts_with(group))
        .map(|r| value(r.1[k]))
        .collect()
}

/// S's failed link tests per handle, `ℓ_s − (V − V_out)` over g (S contracts only after a passed
/// test, and each contraction removes one vertex; not so for RS, which also contracts untested).
fn failed_per_handle(link_tests: f64, vertices: f64, output_vertices: f64, genus: f64) -> f64 {
    (link_tests - (vertices - output_vertices)) / genus
}

/// Edges of a closed triangulation of genus `g` with `v` vertices: `3v + 6g − 6`.
fn edges_of(vertices: f64, genus: f64) -> f64 {
    3.0 * vertices + 6.0 * genus - 6.0
}

/// Item 6: ε_s at high genus, paper against ours: how many tests fail, and how many edges besides
/// the output's are tested twice (the paper's output edges are bounded by its ε_bf: BF tests every
/// output edge in its last two passes).
fn eps_at_high_genus(rows: &[Row]) -> String {
    // The paper's failed tests: V_out is not given; ≤ 13·g (Table 10's ε_bf bounds the output's
    // edges), small beside V, so it is left out (a lower bound).
    let paper: Vec<String> = ["C0", "C4", "C7", "D0", "D6", "D9"]
        .iter()
        .filter_map(|name| {
            let c = numbers::IRREDUCIBLE_COUNTS.iter().find(|c| c.0 == *name)?;
            let size = numbers::IRREDUCIBLE_SIZES.iter().find(|s| s.0 == *name)?;
            let (v, g) = (value(size.1), value(size.4));
            let (l_s, eps_s, eps_bf) = (value(c.2), value(c.4), value(c.5));
            let fail_s = failed_per_handle(l_s, v, 0.0, g);
            // ε_s − ε_bf: a lower bound on the edges besides the output's tested twice.
            let beyond_bf = if eps_s > eps_bf {
                format!(", ε_s − ε_bf {:.0}·g", (eps_s - eps_bf) / g)
            } else {
                String::new()
            };
            Some(format!(
                "{name} (n_f {}): ε_s {:.0}·g{beyond_bf}, S's failed tests {:.0}·g, ε_s / failed \
                 {:.2}",
                size.3,
                eps_s / g,
                fail_s,
                eps_s / g / fail_s
            ))
        })
        .collect();
    let ours: Vec<String> = rows
        .iter()
        .filter(|r| r.genus >= 10 && matches!(r.group.as_str(), "C" | "D"))
        .filter(|r| ["C0", "C4", "C7", "D0", "D6", "D9"].contains(&r.input.as_str()))
        .map(|r| {
            let g = r.genus as f64;
            let v = r.vertices as f64;
            let fail_s = failed_per_handle(r.s.link_tests, v, r.s.output_vertices, g);
            let eps = r.s.edges_tested_more_than_once;
            format!(
                "{} (n_f {}): ε_s {:.1}·g, ε_s − output edges {:.1}·g, S's failed tests {:.0}·g, \
                 ε_s / failed {:.2}",
                r.input,
                number(r.faces as f64, 0),
                eps / g,
                (eps - edges_of(r.s.output_vertices, g)) / g,
                fail_s,
                eps / g / fail_s
            )
        })
        .collect();
    format!(
        "- **ε_s at high genus (item 6)** — paper: {}. Ours: {}. The paper's ε_s/g depends on how \
         finely each of its 3,844 pits is triangulated (≈ 99·g at every genus of D, falling with \
         n_f to 13·g on C); ε_bf bounds its output's edges (BF tests each of them in its last two \
         passes), so on C0 and D0 its S tests at least 84·g edges *besides the output's* more \
         than once (ε_s − ε_bf), a quarter of its failed tests. Ours tests almost only the output's edges \
         twice (each from both ends): ε_s − output edges is given above for this run, and on the \
         reduced bricks below it is 0.2·g (D0-like: ε_s 17.2·g, output edges 17.0·g), 0.7·g \
         (11,000 triangles per pit) and 2.4·g (D9-like). Measured on reduced bricks of 60 pits \
         (`cargo run --release -p surftopo-bench --example schipper_epsilon`): (i) **Counting.** \
         The paper fixes ε as \"the number of edges tested more than once by S\" (Section 5.3), \
         which ours counts (edge ids, which survive contractions). Counted otherwise from the same \
         tests — an edge merged by a contraction identified by the other record of the two ([v, x] \
         rather than the kept [u, x]), by both records, or by its two end vertices, or repeated \
         tests instead of edges — ε_s on a D0-like brick (55 holes, 1,100 triangles per pit, as \
         D0) is 19.9, 17.0, 16.5 and 20.2·g against our 17.2·g, and at 11,000 triangles per pit \
         26.3, 15.4, 12.9 and 33.8·g against 16.1·g; counts per half-edge or per (vertex, edge) \
         pair are subsets of the per-edge count. None comes near 99·g: the counting does not \
         explain it. (ii) **S itself.** Section 3 describes S by \"the edge chosen to be tested \
         against the link condition is always incident on a vertex of lowest degree\" and a global \
         dictionary that \"stores all vertices of K indexed by their current degree\", and leaves \
         open which end survives a contraction; Section 5.3 observes that \"a few low degree \
         vertices are chosen over and over again by S before they become trapped, and several \
         edges incident on these vertices are tested more than once against the link condition and \
         failed the test\". Ours removes the chosen vertex, so it never chooses a vertex twice. \
         Keeping it instead (variant `ChosenKept`) lets vertices be chosen again and gives ε_s \
         19.9 and 28.9·g (D0-like, then 11,000 triangles per pit), but a contraction then costs \
         O(d_w) instead of O(d_v): 19.4 s against our 0.39 s at 11,000 triangles per pit \
         (quadratic where high-degree vertices form), against the O(n_f lg n_f + g lg n_f + g⁴) \
         the paper states for S; keeping the end that the edge's first half-edge leaves (either \
         end, variant `EdgeOrientation`) gives 18.2 and 19.8·g. So ours keeps removing the chosen \
         vertex. (iii) **Variants** (D0-like, then 11,000 triangles per pit): trapped and link \
         vertices put back into the global dictionary after each contraction, ε_s 17.2 and 16.2·g \
         (the re-tests fall on the output's edges, already counted); edges tried by increasing id \
         of the other end 16.8 and 22.4·g, by its degree 13.1 and 13.5·g; rotation order from a \
         vertex-dependent start 13.5 and 13.3·g; the chosen vertex kept and chosen again at once \
         while its degree is at most 6, 22.6 and 75.9·g (ε_s / failed 0.26 and 0.20: the only \
         variant whose ε_s grows with the triangles per pit as the paper's does, still a quarter \
         of the paper's 99·g at D0's 1,100 triangles per pit); chosen again until trapped, 58.1·g \
         at 110 triangles per pit (quadratic, not run finer). Other inputs (55 one-square holes in \
         wide walls, holes 100 steps long, 200,000 random flips): ours 20.1, 16.0 and 14.5·g, no \
         variant above 24·g. S's failed tests per handle depend on the order the edges are tried \
         and on the input (33 to 553·g over the variants and inputs above; the paper's 352·g is \
         within), ε_s does not. **Cause: a faithful difference.** The count is the paper's and \
         ours follows Section 3's description, under which a chosen vertex is removed or trapped \
         and so never chosen again; the paper's implementation chooses vertices again (its \
         Section 5.3 says so) and re-tests the edges that failed around them, a quarter of its \
         failures. Choosing again is the only change measured that makes ε_s grow with the \
         triangles per pit as the paper's does (22.6 → 75.9·g), but the paper does not say \
         when a vertex is chosen again, none of the readings tried reaches its 99·g at D0's \
         fineness, and those that choose again until trapped are quadratic, against the bound \
         the paper states for S; so ours keeps Section 3's reading.\n",
        paper.join("; "),
        if ours.is_empty() {
            "no input of group C or D run".into()
        } else {
            ours.join("; ")
        },
    )
}

/// Time per link test of one algorithm over RS's: (t_x/t_rs) / (ℓ_x/ℓ_rs), from ratio columns
/// `l` (ℓ ratio) and `t` (time ratio) of Tables 7, 9, 11.
fn time_per_test(l: f64, t: f64) -> f64 {
    t / l
}

/// The section of `irreducible.md`.
pub fn irreducible(rows: &[Row]) -> String {
    let mut md = String::from("## Where we differ from the paper\n\n");
    md += "Inputs (issue item 9): groups B and C are made as the paper made them — B0 and C0 \
           bricks, each B_i (C_i) the previous one simplified to the paper's triangle count — \
           and BF runs ten times per input (seeds 1..=10), as in the paper, except above a \
           million triangles (three seeds: see the top of this report). The bricks are our \
           polycube (`CavityBox`): the paper gives only counts, so V, E, F differ from Tables \
           3–5 by the fraction shown in the size tables; the simplification is random \
           link-condition contraction (the paper's process is not named), so the simplified \
           inputs share the paper's F and genus, not its connectivity.\n\n";
    md += &s_against_bf(rows);
    md += &bf_against_rs(rows);
    md += &s_against_rs_on_the_first_group(rows);
    let _ = writeln!(md, "{}", eps_at_high_genus(rows));
    md += &b7(rows);
    md
}

/// Item 3 of `irreducible.md`'s differences: t_s/t_bf and the time per link test.
fn s_against_bf(rows: &[Row]) -> String {
    let mut md = String::new();
    let ts_bf: Vec<String> = ["B", "C", "D"]
        .iter()
        .map(|g| {
            format!(
                "{g}: ours {} (paper {})",
                range(&group_ratio(rows, g, 5)),
                range(&paper_ratio(g, 5))
            )
        })
        .collect();
    let per_test = |f: fn(&Row) -> (f64, f64)| -> String {
        let mut v: Vec<(usize, f64)> = rows
            .iter()
            .filter(|r| r.group != "first")
            .map(|r| {
                let (t, l) = f(r);
                (r.faces, 1e9 * t / l.max(1.0))
            })
            .collect();
        v.sort_by_key(|x| x.0);
        match (v.first(), v.last()) {
            (Some(a), Some(b)) => format!(
                "{:.0} ns at {} triangles, {:.0} ns at {}",
                a.1, a.0, b.1, b.0
            ),
            _ => "not run".into(),
        }
    };
    let _ = writeln!(
        md,
        "- **S against BF (item 3)** — t_s/t_bf, {}. ℓ_s < ℓ_bf everywhere, as in the paper \
         (Tables 6, 8, 10), so the difference is in the time per link test: CPU time per test, \
         BF {}; S {}. BF's cost per test grows with n much more than S's: BF visits the edges in \
         a random order (its shuffle), so at millions of triangles nearly every test and \
         contraction misses the caches, while S works around one low-degree vertex at a time. \
         The paper's BF, on a machine with a 4 MB cache, did not show this growth as strongly \
         (its t_s/t_bf stays above 1 on B0–B2). Measured cause of the trend; the size of the \
         effect on the paper's machine is not known.\n",
        ts_bf.join("; "),
        per_test(|r| (r.bf.cpu_seconds, r.bf.link_tests)),
        per_test(|r| (r.s.cpu_seconds, r.s.link_tests)),
    );
    md
}

/// Item 4: t_bf/t_rs, and its trend on group C.
fn bf_against_rs(rows: &[Row]) -> String {
    let mut md = String::new();
    let tbf: Vec<String> = ["B", "C", "D"]
        .iter()
        .map(|g| {
            format!(
                "{g}: ours {} (paper {})",
                range(&group_ratio(rows, g, 4)),
                range(&paper_ratio(g, 4))
            )
        })
        .collect();
    let ours_c: Vec<String> = rows
        .iter()
        .filter(|r| r.group == "C")
        .map(|r| {
            let q = ratios(r);
            format!("{} {:.1}", r.input, time_per_test(q[1], q[4]))
        })
        .collect();
    let paper_c: Vec<String> = numbers::IRREDUCIBLE_RATIOS
        .iter()
        .filter(|r| r.0.starts_with('C'))
        .map(|r| format!("{} {:.1}", r.0, time_per_test(value(r.1[1]), value(r.1[4]))))
        .collect();
    let _ = writeln!(
        md,
        "- **t_bf/t_rs (item 4)** — {}. The ℓ ratios ℓ_bf/ℓ_rs agree with the paper's (Tables \
         7, 9, 11 above), so the time ratio comes from the cost per test, and BF's grows with n \
         (item 3: random edge order, cache misses), which is why D (4.2M triangles) has the \
         largest t_bf/t_rs. **Trend on C** (fixed genus, n falling from C0 to C7): the paper's \
         t_bf/t_rs rises from 2.39 to 58.88 while its ℓ_bf/ℓ_rs only goes from 1.03 to 3.46. \
         Measured: BF's time per link test over RS's, (t_bf/t_rs)/(ℓ_bf/ℓ_rs), is in the \
         paper {}; ours {}. So the paper's BF spends, as the input shrinks at genus 3,500, more \
         and more time outside its link tests (up to 17 RS-tests' worth per test on C7), which \
         the counts it reports do not include. The paper describes BF's passes (shuffled \
         array, failures to an auxiliary array, repeated until a pass contracts nothing), \
         which ours follows, but not how its link test is computed; ours marks the link of \
         one end and scans the other's, O(d_u + d_v). A test whose cost grows faster with the \
         degrees would give the paper's trend: at genus 3,500 the degrees grow as the \
         triangles per handle fall (mean degree 2E/V 6.0 on the paper's C0, 8.5 on C7, and \
         far higher near the irreducible end). The link tests — what the paper counts — \
         agree; the reversed time trend is the paper's BF overhead, not a difference of the algorithm.\n",
        tbf.join("; "),
        paper_c.join(", "),
        if ours_c.is_empty() {
            "not run".into()
        } else {
            ours_c.join(", ")
        }
    );
    md
}

/// Item 5: t_s/t_rs on the first group, and n against the model.
fn s_against_rs_on_the_first_group(rows: &[Row]) -> String {
    let mut md = String::new();
    let first: Vec<String> = rows
        .iter()
        .filter(|r| r.group == "first")
        .map(|r| {
            let q = ratios(r);
            format!(
                "{} ({} F, g {}) {:.2} (ℓ_s/ℓ_rs {:.2}, per test {:.1})",
                r.input,
                r.faces,
                r.genus,
                q[3],
                q[0],
                time_per_test(q[0], q[3])
            )
        })
        .collect();
    let _ = writeln!(
        md,
        "- **t_s/t_rs on the first group (item 5)** — paper: Socket 2.13, Iphigenia 7.55 (the \
         only two values it prints for this group, on two models); ours: {}. ℓ_s/ℓ_rs is \
         between 0.9 and 1.8, so the time ratio is mostly S's cost per link test over RS's \
         (\"per test\"). **n against model**, measured on one surface at several sizes, each \
         simplified (random link-condition contractions) or midpoint-subdivided and then \
         simplified to the count (`cargo run --release -p surftopo-bench --example \
         schipper_time -- ../shared/meshes/pegasus.off.gz 1696 5000 16000 63548 254192 703512 \
         1016768`, and likewise `socket.off.gz 1696 6784 27136 108544 434176`): on the \
         Iphigenia stand-in (genus 5) t_s/t_rs is 6.50 at 1,696 triangles (Socket's size), \
         5.19 at 5,000, 6.56 at 16,000, 4.21 at 63,548, 4.33 at 254,192, 3.44 at 703,512 \
         (Iphigenia's size), 2.48 at 1,016,768; on the paper's own Socket (genus 7) 6.65 at \
         1,696, 5.98 at 6,784, 4.88 at 27,136, 3.79 at 108,544, 3.25 at 434,176 \
         (timings below 20 ms vary by about ±40% between runs on this shared machine). On one surface ours falls as n grows, as the \
         paper's group B does (12.28 → 3.56): n does not make it rise, so the paper's rise \
         from Socket to Iphigenia is a difference between its two models (its Iphigenia mesh \
         is not available here) or of its implementation, not of n. S's set-up (the \
         dictionaries) is 12–24% of t_s at every size, so our higher level at small n (Socket: \
         ours several times the paper's 2.13; these timings are of 0.1–1 ms, repeated for \
         half a second) is S's cost per test against our RS's, which is relatively faster \
         on small inputs than the paper's.\n",
        if first.is_empty() {
            "not run".into()
        } else {
            first.join(", ")
        }
    );
    md
}

/// Item 8: ℓ_rs on B7 (empty when B7 was not run).
fn b7(rows: &[Row]) -> String {
    let mut md = String::new();
    if let Some(b7) = rows.iter().find(|r| r.input == "B7") {
        let _ = writeln!(
            md,
            "- **B7 (item 8)** — made as in the paper (B6 simplified): ℓ_rs {:.0} against \
             the paper's 14,085. ℓ_rs on a simplified input depends on its connectivity, which \
             differs from the paper's (random contractions against the paper's unnamed \
             process).\n",
            b7.rs.link_tests
        );
    }
    md
}

/// The section of `quad.md`.
pub fn quad(records: &[QuadRecord], scale: Scale) -> String {
    let mut md = String::from("## Where we differ from the paper\n\n");
    md += "Inputs (issue item 9): A2–A5 and B2–B5 are made as the paper made them, by \
           simplifying A1 and B1 (here step by step, random link-condition contractions, to \
           the paper's triangle counts; the paper used Graphite's simplification, which also \
           keeps the shape); SG and PS run ten seeds, as in the paper, except above a million \
           triangles (three seeds: see the top of this report). None of the paper's \
           models of Table 4.1 is available: each is a stand-in.\n\n";
    let flips: Vec<String> = records
        .iter()
        .filter(|r| r.algorithm == "LRS")
        .map(|r| {
            format!(
                "{} {:.1}%",
                r.input,
                100.0 * r.flipped_edges / r.edges as f64
            )
        })
        .collect();
    let botijo = |name: &str, alg: &str| {
        records
            .iter()
            .find(|r| r.input == name && r.algorithm == alg)
    };
    let rebuilt = match (
        botijo("Botijo (simplified)", "LRS"),
        botijo("Botijo (simplified)", "SG"),
    ) {
        (Some(l), Some(g)) => format!(
            " Botijo rebuilt at the paper's size (botijo_41k simplified to 40,016 triangles: \
             the paper's V, E, F and genus) gives LRS {:.1}% flipped edges, (c) {:.0} for LRS \
             (paper 62.0) and {:.1} for SG (paper 5,023.8).",
            100.0 * l.flipped_edges / l.edges as f64,
            l.unpaired,
            g.unpaired
        ),
        _ => String::new(),
    };
    let _ = writeln!(
        md,
        "- **LRS flips (item 1)** — paper: 5–10% of the edges (Botijo 3,392 of 60,024, \
         5.7%); ours: {}. Measured cause: the connectivity of the input. LRS flips far more on \
         regular meshes (botijo_41k is a uniform remesh; the bricks A1 and B1 are polycubes) \
         than on the same surfaces made irregular by simplification (A2–A5, B2–B5, the \
         simplified Botijo), which fall in or near the paper's range.{rebuilt} Our count is \
         the number of input edges whose flip is in K (`QuadStats::flipped_edges`); the paper \
         does not define its count.\n",
        flips.join(", ")
    );
    let ps_a: Vec<String> = records
        .iter()
        .filter(|r| r.algorithm == "PS" && r.group == "A")
        .map(|r| format!("{} {:.1}", r.input, r.unpaired))
        .collect();
    let ps = |name: &str| {
        botijo(name, "PS").map_or("not run".to_string(), |r| format!("{:.1}", r.unpaired))
    };
    let paired = |alg: &str, stand_ins: bool| -> Vec<f64> {
        records
            .iter()
            .filter(|r| r.algorithm == alg && (r.group == "first") == stand_ins)
            .filter(|r| stand_ins || r.group == "A")
            .map(|r| r.paired_percent)
            .collect()
    };
    let _ = writeln!(
        md,
        "- **PS on group A (item 2)** — paper: 136 unpaired on A1 (α = 3.2·10⁻⁵), 621–733 on \
         A2–A5 (α up to 2.1·10⁻³ at A5); ours: {}. Measured: (i) PS's pairing ratio on the \
         real stand-in meshes is the paper's (ours {}% paired, paper 99.87–99.99% on Table \
         4.3), and SG's on group A is the paper's \"about 87%\" (ours {}%), so neither the \
         counting nor the dual graph differs; (ii) PS leaves few triangles on a regular real \
         mesh (botijo_41k: {} against the paper's 10.6 on its Botijo) and many on our \
         simplified meshes (Botijo simplified to the paper's size: {}; A2–A5): our \
         simplification (random link-condition contractions, no shape criterion) makes the \
         connectivity far more irregular than Graphite's, and the paper itself finds PS \
         \"affected by the triangulation connectivity regularity\" (Section 4) — this is the \
         excess at A5, where α is above the paper's range; (iii) on A1, a brick in both, the \
         unpaired triangles are where PS's single front meets itself, so their number \
         depends on the brick's geometry (ours a polycube: flat grids of one diagonal \
         meeting at right-angled creases around every pit; the paper's geometry is not \
         given) and on which triangle PS takes from its highest set, which the paper leaves \
         open (\"any triangle\"; ours the last one inserted). The priority rules themselves \
         are tested against the paper's definition after every step \
         (`pulli_segal::tests`). A different input, not a deviation found in the code.\n",
        if ps_a.is_empty() {
            "not run".into()
        } else {
            ps_a.join(", ")
        },
        range(&paired("PS", true)),
        range(&paired("SG", false)),
        ps("Botijo"),
        ps("Botijo (simplified)")
    );
    let ds: Vec<String> = records
        .iter()
        .filter(|r| r.algorithm == "DS")
        .filter_map(|d| {
            let l = records
                .iter()
                .find(|l| l.algorithm == "LRS" && l.group == d.group && l.input == d.input)?;
            Some(format!(
                "{} {:.2}",
                d.input,
                l.total_seconds / d.total_seconds.max(1e-12)
            ))
        })
        .collect();
    let ds_botijo = botijo("Botijo (simplified)", "DS").map_or(String::new(), |d| {
        format!(
            " On Botijo at the paper's size our DS takes {:.2} s against the paper's 1.93 s: \
             our DS is not slower than the paper's.",
            d.total_seconds
        )
    });
    let _ = writeln!(
        md,
        "- **DS against LRS (item 7)** — paper: t_LRS/t_DS = 1.12 on B1, 3.7 on B5 (DS faster); \
         ours (t_LRS/t_DS): {}. Measured cause: LRS's augmentation. The paper's LRS spends \
         1,381 of its 1,395 s on B1 in augmentation (d); ours also leaves thousands of \
         triangles unpaired on group B ((c) above), but its default `forest` search pairs them in a small fraction of that, and even the paper's global \
         search, in our implementation, is far faster than the paper's (table \"Augmentation \
         with the paper's search\").{ds_botijo}\n",
        if ds.is_empty() {
            "not run".into()
        } else {
            ds.join(", ")
        }
    );
    if scale != Scale::Full {
        md += "\nThis is a reduced run: the sizes and times above are not comparable with the \
               paper's; see the full run for the comparison.\n";
    }
    md
}

/// The section of `intrinsic.md`.
pub fn intrinsic(records: &[IntrinsicRecord]) -> String {
    let mut md = String::from("## Where we differ from the paper\n\n");
    let wrong: Vec<String> = records
        .iter()
        .filter(|r| r.kind == "flat_torus")
        .filter(|r| {
            r.status != "ok"
                || Some(r.flips) != r.expected_flips
                || r.length_error.is_none_or(|e| e >= 1e-6)
        })
        .map(|r| format!("x = {:e}", r.parameter))
        .collect();
    if wrong.is_empty() {
        md += "Nowhere on T_x: every x measured gives D_x (x − 1 flips, lengths 1, 2, √5).\n";
    } else {
        let _ = writeln!(
            md,
            "On T_x at {}: the paper's model is the real RAM (exact reals); we flip in double \
             precision, whose rounding grows with the aspect ratio O(x²). This is a faithful \
             difference of arithmetic, not of the algorithm: `flip_to_delaunay` works on \
             `f64` lengths only, while Dubois' Theorem 1 in exact arithmetic \
             (`delaunay --method dubois --exact`) gives D_x for every x (results/dubois_bench.md).",
            wrong.join(", ")
        );
    }
    md
}
