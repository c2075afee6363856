//! A Wavefront OBJ reader for meshes: `v x y z` lines and `f` lines (a
//! polygon of 3 or more 1-based, or negative relative, vertex references,
//! `i`, `i/t`, `i//n` or `i/t/n`), fan-triangulated (a, b, c), (a, c, d), ….
//! Every other line (normals, texture coordinates, groups, materials) is
//! ignored and counted, so the loader can say so. Errors carry the line
//! and the column (1-based) of the offending word.

/// A parsed OBJ file: vertices, triangles, and where each triangle came from.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Obj {
    pub vertices: Vec<[f64; 3]>,
    pub triangles: Vec<[usize; 3]>,
    /// For each triangle, the line and column of its `f`.
    pub triangle_at: Vec<(usize, usize)>,
    /// The kinds of line ignored (`vn`, `vt`, `g`, …) and how many of each.
    pub ignored: Vec<(String, usize)>,
}

/// A problem at a line and column (1-based).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("line {line}, column {column}: {message}")]
pub struct ObjError {
    pub line: usize,
    pub column: usize,
    pub message: String,
}

/// Parses OBJ text.
pub fn parse(text: &str) -> Result<Obj, ObjError> {
    let mut obj = Obj::default();
    for (n, raw) in text.lines().enumerate() {
        let line = n + 1;
        let content = raw.split('#').next().unwrap_or("");
        let mut words = words_with_columns(content);
        let Some((column, keyword)) = words.next() else {
            continue;
        };
        let err = |column: usize, message: String| ObjError {
            line,
            column,
            message,
        };
        match keyword {
            "v" => {
                let mut xyz = [0.0; 3];
                for (k, x) in xyz.iter_mut().enumerate() {
                    let (c, w) = words.next().ok_or_else(|| {
                        err(column, format!("a vertex needs 3 coordinates, got {k}"))
                    })?;
                    *x = w
                        .parse::<f64>()
                        .ok()
                        .filter(|x| x.is_finite())
                        .ok_or_else(|| err(c, format!("'{w}' is not a finite number")))?;
                }
                obj.vertices.push(xyz);
            }
            "f" => {
                let mut refs = Vec::new();
                for (c, w) in words {
                    let first = w.split('/').next().unwrap_or("");
                    let i: i64 = first
                        .parse()
                        .map_err(|_| err(c, format!("'{w}' is not a vertex reference")))?;
                    let count = obj.vertices.len() as i64;
                    let index = if i > 0 { i - 1 } else { count + i };
                    if i == 0 || index < 0 || index >= count {
                        return Err(err(
                            c,
                            format!("vertex {i} does not exist ({count} vertices so far)"),
                        ));
                    }
                    refs.push(index as usize);
                }
                if refs.len() < 3 {
                    return Err(err(
                        column,
                        format!("a face needs at least 3 vertices, got {}", refs.len()),
                    ));
                }
                for k in 1..refs.len() - 1 {
                    obj.triangles.push([refs[0], refs[k], refs[k + 1]]);
                    obj.triangle_at.push((line, column));
                }
            }
            other => match obj.ignored.iter_mut().find(|(k, _)| k == other) {
                Some((_, count)) => *count += 1,
                None => obj.ignored.push((other.to_string(), 1)),
            },
        }
    }
    Ok(obj)
}

/// The words of a line with their 1-based columns (in characters).
fn words_with_columns(line: &str) -> impl Iterator<Item = (usize, &str)> {
    let mut column = 0;
    let mut start: Option<(usize, usize)> = None;
    let mut out = Vec::new();
    for (byte, ch) in line.char_indices() {
        column += 1;
        if ch.is_whitespace() {
            if let Some((c, b)) = start.take() {
                out.push((c, &line[b..byte]));
            }
        } else if start.is_none() {
            start = Some((column, byte));
        }
    }
    if let Some((c, b)) = start {
        out.push((c, &line[b..]));
    }
    out.into_iter()
}
