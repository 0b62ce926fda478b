//! How deeply an XML text nests, found without recursion, before a recursive reader sees it.
//! It must not parse or judge the XML beyond its depth, and depends on nothing.
//!
//! Both of ergocell's XML readers recurse: `urdf-rs` (the robot's URDF) skips every element it does
//! not know by a call inside a call, and `roxmltree` (a Qualisys calibration) builds its tree the
//! same way, so 50,000 nested elements (350 KB) overflow the stack and abort the process before
//! any check of ours runs. A URDF or a calibration nests a handful of levels (robot → link → visual
//! → geometry → mesh); [`check`] refuses a text that nests deeper than [`MAX_XML_DEPTH`] by scanning
//! it once, iteratively: comments, CDATA, processing instructions and the doctype are skipped,
//! quoted attribute values may hold `>` and `/`. Its own crate, below both readers (robot knows no
//! cameras, perception no robot). TOML needs no such scan: its parser (`toml_edit`) stops at 80
//! levels by itself.

/// The deepest nesting of elements an XML input may have.
pub const MAX_XML_DEPTH: usize = 64;

/// An XML text nested deeper than allowed: how deep, and where (byte offset of the element that
/// went past the limit).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("elements nested more than {max} deep (at byte {at}): a URDF or a calibration nests a handful of levels")]
pub struct TooDeep {
    pub max: usize,
    pub at: usize,
}

/// Scans `text` and refuses it if its elements nest more than `max` deep. Malformed XML is left
/// to the parser to name; only the depth is judged here.
pub fn check(text: &str, max: usize) -> Result<(), TooDeep> {
    let b = text.as_bytes();
    let find = |from: usize, pat: &[u8]| -> usize {
        b.get(from..)
            .and_then(|rest| rest.windows(pat.len()).position(|w| w == pat))
            .map_or(b.len(), |p| from + p + pat.len())
    };
    let mut depth = 0usize;
    let mut i = 0usize;
    while i < b.len() {
        if b[i] != b'<' {
            i += 1;
            continue;
        }
        let at = i;
        let rest = &b[i + 1..];
        if rest.starts_with(b"!--") {
            i = find(i + 4, b"-->");
        } else if rest.starts_with(b"![CDATA[") {
            i = find(i + 9, b"]]>");
        } else if rest.starts_with(b"?") {
            i = find(i + 2, b"?>");
        } else if rest.starts_with(b"!") {
            // <!DOCTYPE …> with an optional [internal subset]
            let mut j = i + 2;
            let mut bracket = 0usize;
            while j < b.len() {
                match b[j] {
                    b'[' => bracket += 1,
                    b']' => bracket = bracket.saturating_sub(1),
                    b'>' if bracket == 0 => break,
                    _ => {}
                }
                j += 1;
            }
            i = j + 1;
        } else {
            // A start, end or empty-element tag: to its '>' outside quotes.
            let end_tag = rest.starts_with(b"/");
            let mut j = i + 1;
            let mut quote: Option<u8> = None;
            while j < b.len() {
                let c = b[j];
                match quote {
                    Some(q) if c == q => quote = None,
                    None if c == b'"' || c == b'\'' => quote = Some(c),
                    None if c == b'>' => break,
                    _ => {}
                }
                j += 1;
            }
            let empty = j > 0 && b.get(j - 1) == Some(&b'/');
            if end_tag {
                depth = depth.saturating_sub(1);
            } else if !empty {
                depth += 1;
                if depth > max {
                    return Err(TooDeep { max, at });
                }
            }
            i = j + 1;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nested(n: usize) -> String {
        format!("<robot>{}{}</robot>", "<a>".repeat(n), "</a>".repeat(n))
    }

    #[test]
    fn depth_is_counted_without_recursion() {
        assert_eq!(check(&nested(10), 11), Ok(()));
        assert_eq!(
            check(&nested(11), 11),
            Err(TooDeep {
                max: 11,
                at: 7 + 10 * 3
            })
        );
        // 5 million levels: scanned, refused, no stack used.
        assert!(check(&nested(5_000_000), MAX_XML_DEPTH).is_err());
    }

    #[test]
    fn comments_cdata_doctype_quotes_and_empty_elements_do_not_nest() {
        let text = r#"<?xml version="1.0"?>
<!DOCTYPE robot [ <!ENTITY x "<a><a>"> ]>
<!-- <a><a><a> -->
<robot name="r>/">
  <link name="a"/><link name='b>'></link>
  <![CDATA[ <a><a><a> ]]>
</robot>"#;
        assert_eq!(check(text, 2), Ok(()));
        // robot > link: two levels; the comment, CDATA, entity and quoted `>` add none.
        assert!(check(text, 1).is_err());
        assert!(check("<a><b><c/></b></a>", 1).is_err());
        assert!(check("<a><b><c/></b></a>", 2).is_ok());
    }
}
