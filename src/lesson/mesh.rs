//! A lesson's mesh (`shape = { mesh = … }`) as a physics [`Shape::Mesh`]:
//! inline vertices and triangles, or an OBJ file next to the lesson. A
//! movable mesh must be closed; it is re-centred on its solid's centroid
//! as a hull is (the offset is returned, the body's position moves by it).

use std::sync::Arc;

use nalgebra::Vector3;

use super::raw::RawMesh;
use crate::physics::mesh::{obj, MeshError, TriMesh};
use crate::physics::Shape;

/// The mesh shape, the centre of mass's offset from the file's frame, and
/// a note for the lines of an OBJ file that were ignored; or why it is refused.
pub fn from_raw(
    raw: &RawMesh,
    origin: &str,
    movable: bool,
) -> Result<(Shape, Vector3<f64>, Option<String>), String> {
    let (vertices, triangles, source) = match raw {
        RawMesh::Inline {
            vertices,
            triangles,
        } => (vertices.clone(), triangles.clone(), None),
        RawMesh::File(name) => {
            let (path, text) = read_obj(name, origin)?;
            let parsed = obj::parse(&text).map_err(|e| {
                format!(
                    "{path}:{}:{}: {}",
                    e.line,
                    e.column,
                    crate::lesson::ascii_minus(&e.message)
                )
            })?;
            (
                parsed.vertices.clone(),
                parsed.triangles.clone(),
                Some((path, parsed)),
            )
        }
    };
    let at = |t: Option<usize>| match (&source, t) {
        (Some((path, parsed)), Some(t)) => parsed
            .triangle_at
            .get(t)
            .map(|(l, c)| format!("{path}:{l}:{c}: "))
            .unwrap_or_else(|| format!("{path}: ")),
        (Some((path, _)), None) => format!("{path}: "),
        (None, _) => String::new(),
    };
    let refuse = |e: MeshError| format!("{}the mesh is refused: {e}", at(e.triangle()));
    let mesh = TriMesh::new(&vertices, &triangles).map_err(refuse)?;
    let note = source.as_ref().and_then(|(path, parsed)| {
        (!parsed.ignored.is_empty()).then(|| {
            let kinds: Vec<String> = (parsed.ignored.iter())
                .map(|(k, n)| format!("{n} `{k}`"))
                .collect();
            format!(
                "{path}: lines ignored (a mesh reads only `v` and `f`): {}",
                kinds.join(", ")
            )
        })
    });
    if !movable {
        return Ok((Shape::Mesh(Arc::new(mesh)), Vector3::zeros(), note));
    }
    if let Some((t, k)) = open_edge(&mesh) {
        let [a, b] = [mesh.triangles()[t][k], mesh.triangles()[t][(k + 1) % 3]];
        return Err(refuse(MeshError::Open { triangle: t, a, b }));
    }
    let Some(mass) = mesh.mass_properties() else {
        return Err(refuse(MeshError::InsideOut));
    };
    let centred = mesh.translated(&-mass.centroid);
    Ok((Shape::Mesh(Arc::new(centred)), mass.centroid, note))
}

/// The first triangle edge with no neighbour (triangle, edge).
fn open_edge(mesh: &TriMesh) -> Option<(usize, usize)> {
    (0..mesh.triangles().len()).find_map(|t| {
        (mesh.neighbours(t).iter())
            .position(Option::is_none)
            .map(|k| (t, k))
    })
}

/// OBJ files larger than this are refused unread.
const MAX_OBJ_BYTES: usize = 64 << 20;

/// The OBJ file's path as shown, and its text. An embedded lesson has no
/// folder: its meshes are written inline.
fn read_obj(name: &str, origin: &str) -> Result<(String, String), String> {
    if origin.ends_with("(embedded)") {
        return Err(format!(
            "an embedded lesson's mesh is written inline (vertices and triangles), not read from '{name}'"
        ));
    }
    let dir = std::path::Path::new(origin)
        .parent()
        .unwrap_or(std::path::Path::new(""));
    let path = dir.join(name);
    let shown = path.display().to_string();
    let bytes = super::read::read_regular(&path, MAX_OBJ_BYTES)
        .map_err(|_| format!("the mesh file '{shown}' cannot be read"))?;
    let text = String::from_utf8(bytes).map_err(|e| {
        format!(
            "the mesh file '{shown}' is not UTF-8 text (byte {})",
            e.utf8_error().valid_up_to()
        )
    })?;
    Ok((shown, text))
}
