//! The bound on a deck's arrays (issue 24 item 7), checked on the raw text before any
//! TOML document is built: the editable document keeps spans, decor and a table entry
//! for every value, ≈ 2.3 kB a `[u, µ]` pair, so a 4 MiB deck of
//! `points = [[0,0],…]` (700 000 pairs) peaked at 1.63 GB in `check` before its first
//! point was even judged. No deck needs more than a few hundred entries in an array (a
//! traction table of a measured curve, a thermal network's nodes and links), so an array
//! (inline, or an array of tables `[[…]]`) of more than [`MAX_ARRAY_LEN`] elements, or a
//! deck of more than [`MAX_DECK_VALUES`] array elements in all, is refused with its key
//! and line.
//!
//! The scan knows just enough TOML to find arrays: strings (basic, literal, and their
//! multi-line forms, with escapes), comments, table headers at the start of a line, and
//! brackets and braces inside values. It never fails on text the parser would reject:
//! that is left to the parser's own message.

use super::{DeckError, DeckErrors, Location};

/// The most elements one array of a deck may hold (an inline array's, or the entries of
/// one array of tables).
pub const MAX_ARRAY_LEN: usize = 10_000;
/// The most array elements a deck may hold in all (nested ones counted: a `[u, µ]` pair
/// is three, the pair and its two numbers): ≈ 40 MB of parsed document.
pub const MAX_DECK_VALUES: usize = 50_000;

/// One open array or inline table.
struct Open {
    /// An array (counted) or an inline table (`{…}`, not counted).
    array: bool,
    /// Elements begun so far.
    elements: usize,
    /// Whether a value has begun since the last separator.
    pending: bool,
}

/// Refuses `text` when an array holds more than [`MAX_ARRAY_LEN`] elements or the deck
/// more than [`MAX_DECK_VALUES`], naming the key and the line.
pub fn check_arrays(text: &str, source: &str) -> Result<(), DeckErrors> {
    let b = text.as_bytes();
    let mut i = 0;
    let mut stack: Vec<Open> = Vec::new();
    // The current table (from the last header) and the key of the value being read.
    let mut table = String::new();
    let mut key = String::new();
    let mut line_start = true;
    let mut total = 0usize;
    // Entries of each array of tables `[[name]]`.
    let mut headers: std::collections::HashMap<String, usize> = Default::default();
    let refuse = |at: usize, key: &str, what: String| -> DeckErrors {
        DeckError::Invalid {
            location: Location::at(source, text, at),
            key: key.to_string(),
            value: "[…]".into(),
            rule: what,
        }
        .into()
    };
    while i < b.len() {
        let c = b[i];
        match c {
            b'\n' => {
                if stack.is_empty() {
                    line_start = true;
                }
                i += 1;
                continue;
            }
            b' ' | b'\t' | b'\r' => {
                i += 1;
                continue;
            }
            b'#' => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
                continue;
            }
            _ => {}
        }
        // A value begins inside the innermost array.
        if let Some(top) = stack.last_mut() {
            if top.array && !top.pending && c != b']' && c != b',' {
                top.pending = true;
                top.elements += 1;
                total += 1;
                let full = if table.is_empty() {
                    key.clone()
                } else {
                    format!("{table}.{key}")
                };
                if top.elements > MAX_ARRAY_LEN {
                    return Err(refuse(
                        i,
                        &full,
                        format!(
                            "holds more than {MAX_ARRAY_LEN} elements (element {} is on this line); a deck's array holds at most {MAX_ARRAY_LEN}",
                            top.elements
                        ),
                    ));
                }
                if total > MAX_DECK_VALUES {
                    return Err(refuse(
                        i,
                        &full,
                        format!(
                            "the deck's arrays hold more than {MAX_DECK_VALUES} elements in all by this line; a deck holds at most {MAX_DECK_VALUES}"
                        ),
                    ));
                }
            }
        }
        match c {
            b'[' if stack.is_empty() && line_start => {
                // A table header: `[name]` or `[[name]]`, to the end of its line.
                let end = b[i..]
                    .iter()
                    .position(|&x| x == b'\n')
                    .map_or(b.len(), |p| i + p);
                let head = text.get(i..end).unwrap_or("");
                let head = head.split('#').next().unwrap_or("").trim();
                let aot = head.starts_with("[[");
                table = head
                    .trim_matches(|x| x == '[' || x == ']')
                    .trim()
                    .to_string();
                if aot {
                    let n = headers.entry(table.clone()).or_insert(0);
                    *n += 1;
                    total += 1;
                    if *n > MAX_ARRAY_LEN {
                        return Err(refuse(
                            i,
                            &table,
                            format!("holds more than {MAX_ARRAY_LEN} [[{table}]] entries; a deck's array holds at most {MAX_ARRAY_LEN}"),
                        ));
                    }
                    if total > MAX_DECK_VALUES {
                        return Err(refuse(
                            i,
                            &table,
                            format!("the deck's arrays hold more than {MAX_DECK_VALUES} elements in all by this line; a deck holds at most {MAX_DECK_VALUES}"),
                        ));
                    }
                }
                i = end;
                continue;
            }
            b'[' => stack.push(Open {
                array: true,
                elements: 0,
                pending: false,
            }),
            b'{' => stack.push(Open {
                array: false,
                elements: 0,
                pending: false,
            }),
            b']' | b'}' => {
                stack.pop();
            }
            b',' => {
                if let Some(top) = stack.last_mut() {
                    top.pending = false;
                }
            }
            b'=' if stack.is_empty() => {
                // The key of this line: the text before `=` on it.
                let from = b[..i]
                    .iter()
                    .rposition(|&x| x == b'\n')
                    .map_or(0, |p| p + 1);
                key = text.get(from..i).unwrap_or("").trim().to_string();
            }
            b'"' | b'\'' => {
                i = skip_string(b, i);
                line_start = false;
                continue;
            }
            _ => {}
        }
        line_start = false;
        i += 1;
    }
    Ok(())
}

/// The index after the string starting at `i` (basic or literal, single- or multi-line);
/// the text's end for an unterminated one.
fn skip_string(b: &[u8], i: usize) -> usize {
    let q = b[i];
    let triple = b.get(i..i + 3) == Some(&[q, q, q][..]);
    let mut j = if triple { i + 3 } else { i + 1 };
    while j < b.len() {
        let c = b[j];
        if c == b'\\' && q == b'"' {
            j += 2;
            continue;
        }
        if !triple && c == b'\n' {
            return j;
        }
        if c == q {
            if !triple {
                return j + 1;
            }
            if b.get(j..j + 3) == Some(&[q, q, q][..]) {
                // Up to two more quotes may close a multi-line string.
                let mut k = j + 3;
                while k < b.len() && b[k] == q && k < j + 5 {
                    k += 1;
                }
                return k;
            }
        }
        j += 1;
    }
    b.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(n: usize) -> String {
        let pts: Vec<String> = (0..n).map(|k| format!("[{k}, 0.01]")).collect();
        format!(
            "type = \"angular-contact-ball\"\n# a [comment] with \"quotes\n[traction_table]\npoints = [\n{}\n]\n",
            pts.join(",\n")
        )
    }

    #[test]
    fn arrays_up_to_the_bound_pass_and_longer_ones_are_refused_with_key_and_line() {
        assert!(check_arrays(&points(MAX_ARRAY_LEN), "d.toml").is_ok());
        let e = check_arrays(&points(MAX_ARRAY_LEN + 1), "d.toml")
            .unwrap_err()
            .to_string();
        // The element past the bound is on line 5 + MAX_ARRAY_LEN.
        let line = format!("d.toml:{}:", 5 + MAX_ARRAY_LEN);
        for want in [
            line.as_str(),
            "traction_table.points",
            "more than 10000 elements",
        ] {
            assert!(e.contains(want), "{want:?} not in {e}");
        }
    }

    #[test]
    fn brackets_in_strings_and_comments_and_headers_are_not_elements() {
        let s = format!(
            "name = \"[[{}]]\"\nnote = '''\n[{}]\n'''\n# [{}]\n[[thermal.nodes]]\nname = \"a\"\n",
            ",".repeat(20_000),
            ",".repeat(20_000),
            ",".repeat(20_000)
        );
        assert!(check_arrays(&s, "d.toml").is_ok());
        let many = "[[thermal.nodes]]\nname = \"n\"\n".repeat(MAX_ARRAY_LEN + 1);
        let e = check_arrays(&many, "d.toml").unwrap_err().to_string();
        assert!(e.contains("thermal.nodes") && e.contains("10000"), "{e}");
        // Many short arrays: the deck's total.
        let total = "[t]\n".to_string() + &"a = [[1, 2], [3, 4]]\n".repeat(MAX_DECK_VALUES / 6 + 1);
        let e = check_arrays(&total, "d.toml").unwrap_err().to_string();
        assert!(e.contains("in all") && e.contains("t.a"), "{e}");
    }
}
