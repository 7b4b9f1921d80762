//! An independent reading of OBJ text for tests: statements split into words and face corners
//! split at their slashes, with nothing of surftopo-io's reader.

/// The statements starting with `keyword ` (e.g. `"vt"`), each split into its words.
pub fn statements<'a>(text: &'a str, keyword: &str) -> Vec<Vec<&'a str>> {
    text.lines()
        .filter_map(|l| l.strip_prefix(keyword).and_then(|r| r.strip_prefix(' ')))
        .map(|r| r.split_whitespace().collect())
        .collect()
}

/// Every face corner in file order: (vertex, `vt`, `vn`), 0-based (positive indices only).
pub fn corners(text: &str) -> Vec<(usize, Option<usize>, Option<usize>)> {
    let part = |s: Option<&str>| {
        s.filter(|s| !s.is_empty())
            .map(|s| s.parse::<usize>().expect("a positive index") - 1)
    };
    statements(text, "f")
        .into_iter()
        .flatten()
        .map(|corner| {
            let mut parts = corner.split('/');
            let v = part(parts.next()).expect("a vertex index");
            (v, part(parts.next()), part(parts.next()))
        })
        .collect()
}
