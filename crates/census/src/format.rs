//! Lutz's lexicographic format: one triangulation per line, `[[1,2,3],[1,2,4],...]`, vertices
//! numbered from 1 (F. H. Lutz, "The Manifold Page"; Sulanke and Lutz 2009).

use crate::canonical::CanonicalForm;
use crate::error::CensusError;
use crate::triangulation::Triangulation;

/// One line (without its newline): the faces with vertices shifted to 1..n.
pub fn to_lutz_line(faces: &[[u32; 3]]) -> String {
    let mut line = String::with_capacity(faces.len() * 10 + 2);
    line.push('[');
    for (i, f) in faces.iter().enumerate() {
        if i > 0 {
            line.push(',');
        }
        line.push_str(&format!("[{},{},{}]", f[0] + 1, f[1] + 1, f[2] + 1));
    }
    line.push(']');
    line
}

/// A census file's text: one line per canonical form, in the order given.
pub fn to_lutz(forms: &[CanonicalForm]) -> String {
    let mut text = String::new();
    for form in forms {
        text.push_str(&to_lutz_line(form.faces()));
        text.push('\n');
    }
    text
}

/// Parses one line of Lutz's format (spaces allowed) into faces with vertices from 0; `line`
/// numbers the errors.
pub fn parse_lutz_line(text: &str, line: usize) -> Result<Vec<[u32; 3]>, CensusError> {
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    let error = |at: usize, message: &str| CensusError::Parse {
        line,
        column: at + 1,
        message: message.to_string(),
    };
    let skip = |i: &mut usize| {
        while *i < chars.len() && chars[*i].is_whitespace() {
            *i += 1;
        }
    };
    let expect = |i: &mut usize, c: char| -> Result<(), CensusError> {
        skip(i);
        if *i < chars.len() && chars[*i] == c {
            *i += 1;
            Ok(())
        } else {
            Err(error(*i, &format!("expected `{c}`")))
        }
    };
    let number = |i: &mut usize| -> Result<u32, CensusError> {
        skip(i);
        let start = *i;
        while *i < chars.len() && chars[*i].is_ascii_digit() {
            *i += 1;
        }
        let digits: String = chars[start..*i].iter().collect();
        match digits.parse::<u32>() {
            Ok(v) if (1..u32::MAX).contains(&v) => Ok(v - 1),
            Ok(_) => Err(error(start, "vertices are numbered from 1")),
            Err(_) => Err(error(start, "expected a vertex number")),
        }
    };
    let mut faces = Vec::new();
    expect(&mut i, '[')?;
    loop {
        expect(&mut i, '[')?;
        let a = number(&mut i)?;
        expect(&mut i, ',')?;
        let b = number(&mut i)?;
        expect(&mut i, ',')?;
        let c = number(&mut i)?;
        expect(&mut i, ']')?;
        faces.push([a, b, c]);
        skip(&mut i);
        if i < chars.len() && chars[i] == ',' {
            i += 1;
            continue;
        }
        expect(&mut i, ']')?;
        break;
    }
    skip(&mut i);
    if i < chars.len() {
        return Err(error(i, "unexpected text after the closing `]`"));
    }
    Ok(faces)
}

/// Parses a census file: one triangulation per non-empty line, each checked to be a closed
/// surface (the error names the line).
pub fn parse_lutz(text: &str) -> Result<Vec<Triangulation>, CensusError> {
    let mut list = Vec::new();
    for (k, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let faces = parse_lutz_line(line, k + 1)?;
        let t = Triangulation::new(faces).map_err(|e| CensusError::InvalidLine {
            line: k + 1,
            source: Box::new(e),
        })?;
        list.push(t);
    }
    Ok(list)
}
