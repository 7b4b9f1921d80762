//! Text copied from input into messages, made safe for a terminal.

use std::borrow::Cow;
use std::fmt::Write as _;

/// `text` with every control character (C0, DEL, C1: ESC, BEL, CR, newline, ...) replaced by an
/// escape (`\n`, `\r`, `\t`, otherwise `\u{1b}`), so that bytes from a file or a path quoted in a
/// message cannot move the cursor, clear the screen or retitle the terminal. Borrowed when there
/// is nothing to escape. Every error message that quotes input goes through this function.
pub fn printable(text: &str) -> Cow<'_, str> {
    if !text.chars().any(char::is_control) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{{{:x}}}", c as u32);
            }
            c => out.push(c),
        }
    }
    Cow::Owned(out)
}

#[cfg(test)]
mod tests {
    use super::printable;

    #[test]
    fn escapes_terminal_controls_only() {
        assert_eq!(printable("plain é"), "plain é");
        assert_eq!(
            printable("\u{1b}]0;title\u{7}\u{1b}[2J\n\u{9b}x\u{7f}"),
            "\\u{1b}]0;title\\u{7}\\u{1b}[2J\\n\\u{9b}x\\u{7f}"
        );
    }
}
