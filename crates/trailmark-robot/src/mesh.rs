//! Triangle meshes of a URDF's collision geometry: OBJ files (read with `tobj`) and STL files,
//! binary or ASCII (read with `stl_io`), and where a URDF's `package://` names lead.
//!
//! ```
//! use trailmark_robot::mesh::Mesh;
//!
//! let mesh = Mesh::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")?;
//! assert_eq!((mesh.vertices.len(), mesh.triangles.len()), (4, 4));
//! # Ok::<(), trailmark_robot::RobotError>(())
//! ```

use std::io::Cursor;
use std::path::{Path, PathBuf};

use nalgebra::Point3;
use trailmark_core::read::read_capped;

use crate::error::RobotError;

/// The largest mesh file read: 256 MiB (a detailed scanned part is a few MiB; a collision mesh
/// is usually kilobytes).
pub const MAX_MESH_BYTES: u64 = 256 << 20;

/// The most triangles of one mesh.
pub const MAX_MESH_TRIANGLES: usize = 2_000_000;

/// A triangle mesh: vertices and triangles of vertex indices, every vertex finite.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    /// The vertices, in the mesh's own frame.
    pub vertices: Vec<Point3<f64>>,
    /// The triangles, three indices into `vertices` each.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// Reads the mesh file at `path`: OBJ or STL by its extension (either case). Errors on a
    /// file that cannot be read or is larger than [`MAX_MESH_BYTES`], another extension, and
    /// what the parsers refuse.
    pub fn from_file(path: impl AsRef<Path>) -> Result<Mesh, RobotError> {
        let path = path.as_ref();
        let fault = |reason: String| RobotError::Mesh { file: path.display().to_string(), reason };
        let bytes = read_capped(path, MAX_MESH_BYTES).map_err(|e| fault(e.to_string()))?;
        let extension = path.extension().map(|e| e.to_string_lossy().to_ascii_lowercase());
        let mesh = match extension.as_deref() {
            Some("obj") => Mesh::parse_obj(&String::from_utf8_lossy(&bytes)),
            Some("stl") => Mesh::parse_stl(&bytes),
            _ => return Err(fault("not an OBJ or STL file (by its extension)".into())),
        };
        mesh.map_err(|e| match e {
            RobotError::Mesh { reason, .. } => fault(reason),
            other => other,
        })
    }

    /// Reads an OBJ text: every object's faces, as triangles (polygons fanned out). Only
    /// positions count: texture coordinates, normals, materials and groups are passed over.
    /// Errors on a face naming a vertex not yet given (or, counting back, before the first),
    /// a face of fewer than three vertices, and more than [`MAX_MESH_TRIANGLES`].
    pub fn parse_obj(text: &str) -> Result<Mesh, RobotError> {
        let text = positions_only(text)?;
        let options = tobj::LoadOptions { triangulate: true, single_index: true, ..Default::default() };
        let (models, _) = tobj::load_obj_buf(&mut Cursor::new(text.as_bytes()), &options, |_| {
            Err(tobj::LoadError::OpenFileFailed)
        })
        .map_err(|e| parse_fault(format!("OBJ: {e}")))?;
        let mut mesh = Mesh { vertices: Vec::new(), triangles: Vec::new() };
        for model in &models {
            let m = &model.mesh;
            let first = mesh.vertices.len();
            let points =
                m.positions.chunks_exact(3).map(|p| Point3::new(p[0].into(), p[1].into(), p[2].into()));
            mesh.vertices.extend(points);
            for t in m.indices.chunks_exact(3) {
                let at = |i: u32| u32::try_from(first + i as usize).ok();
                let [Some(a), Some(b), Some(c)] = [at(t[0]), at(t[1]), at(t[2])] else {
                    return Err(parse_fault("OBJ: more vertices than a mesh takes".into()));
                };
                mesh.triangles.push([a, b, c]);
            }
            mesh.check_size()?;
        }
        mesh.checked()
    }

    /// Reads an STL file's bytes, binary or ASCII.
    pub fn parse_stl(bytes: &[u8]) -> Result<Mesh, RobotError> {
        // A binary file says how many triangles it holds: refuse a count its length cannot
        // hold before anything is read (an ASCII file starts with "solid").
        if !bytes.starts_with(b"solid")
            && let Some(count) = bytes.get(80..84)
        {
            let count = u32::from_le_bytes([count[0], count[1], count[2], count[3]]) as usize;
            if count > MAX_MESH_TRIANGLES {
                return Err(RobotError::TooLarge { what: "an STL mesh", count, max: MAX_MESH_TRIANGLES });
            }
        }
        let stl = stl_io::read_stl(&mut Cursor::new(bytes)).map_err(|e| parse_fault(format!("STL: {e}")))?;
        let vertices =
            stl.vertices.iter().map(|v| Point3::new(v[0].into(), v[1].into(), v[2].into())).collect();
        let mut triangles = Vec::with_capacity(stl.faces.len());
        for face in &stl.faces {
            let [a, b, c] = face.vertices.map(|i| u32::try_from(i).ok());
            let (Some(a), Some(b), Some(c)) = (a, b, c) else {
                return Err(parse_fault("STL: more vertices than a mesh takes".into()));
            };
            triangles.push([a, b, c]);
        }
        let mesh = Mesh { vertices, triangles };
        mesh.check_size()?;
        mesh.checked()
    }

    /// The largest distance of a vertex from the mesh's origin.
    pub fn radius(&self) -> f64 {
        self.vertices.iter().map(|v| v.coords.norm()).fold(0.0, f64::max)
    }

    fn check_size(&self) -> Result<(), RobotError> {
        if self.triangles.len() > MAX_MESH_TRIANGLES {
            return Err(RobotError::TooLarge {
                what: "a mesh's triangles",
                count: self.triangles.len(),
                max: MAX_MESH_TRIANGLES,
            });
        }
        Ok(())
    }

    /// The mesh when it has a triangle, its vertices are finite and its indices in range.
    fn checked(self) -> Result<Mesh, RobotError> {
        if self.triangles.is_empty() {
            return Err(parse_fault("the mesh has no triangles".into()));
        }
        if self.vertices.iter().any(|v| !v.coords.iter().all(|x| x.is_finite())) {
            return Err(parse_fault("a vertex is not finite".into()));
        }
        if self.triangles.iter().flatten().any(|&i| i as usize >= self.vertices.len()) {
            return Err(parse_fault("a triangle names a vertex the mesh does not have".into()));
        }
        Ok(self)
    }
}

/// The `v` lines of an OBJ text and its `f` lines with every vertex as its position's absolute
/// index, each checked: what tobj then reads cannot send it out of range (an index counted back
/// before the first vertex would overflow its arithmetic), and faces cannot outgrow the limit
/// before anything is allocated for them.
fn positions_only(text: &str) -> Result<String, RobotError> {
    let mut out = String::with_capacity(text.len().min(1 << 20));
    let (mut vertices, mut corners) = (0i64, 0usize);
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                vertices += 1;
                out.push_str(line.trim());
                out.push('\n');
            }
            Some("f") => {
                let mut face = String::from("f");
                let mut count = 0;
                for word in words {
                    let position = word.split('/').next().unwrap_or("");
                    let index: i64 =
                        position.parse().map_err(|_| parse_fault(format!("OBJ: a face vertex {word:?}")))?;
                    let absolute = if index < 0 { vertices + index + 1 } else { index };
                    if !(1..=vertices).contains(&absolute) {
                        return Err(parse_fault(format!("OBJ: a face names vertex {index} of {vertices}")));
                    }
                    face.push(' ');
                    face.push_str(&absolute.to_string());
                    count += 1;
                }
                if count < 3 {
                    return Err(parse_fault("OBJ: a face of fewer than three vertices".into()));
                }
                corners += count;
                if corners > 3 * MAX_MESH_TRIANGLES {
                    let max = 3 * MAX_MESH_TRIANGLES;
                    return Err(RobotError::TooLarge {
                        what: "an OBJ mesh's face corners",
                        count: corners,
                        max,
                    });
                }
                out.push_str(&face);
                out.push('\n');
            }
            _ => {}
        }
    }
    Ok(out)
}

fn parse_fault(reason: String) -> RobotError {
    RobotError::Mesh { file: String::new(), reason }
}

/// The file a URDF's mesh `filename` names, for a URDF in the folder `urdf_dir`: a plain path
/// relative to that folder (or absolute); `file://PATH`; or `package://PACKAGE/PATH`, looked
/// for (there being no ROS package index here) as `PACKAGE/PATH` and as `PATH` in the URDF's
/// folder and the three above it, the first that exists. Errors naming the places looked in.
pub fn resolve(filename: &str, urdf_dir: &Path) -> Result<PathBuf, RobotError> {
    let not_found = |tried: &[PathBuf]| RobotError::Mesh {
        file: filename.to_string(),
        reason: format!(
            "not found (looked for {})",
            tried.iter().map(|p| p.display().to_string()).collect::<Vec<_>>().join(", ")
        ),
    };
    if let Some(rest) = filename.strip_prefix("package://") {
        let (package, path) = rest.split_once('/').unwrap_or((rest, ""));
        let mut tried = Vec::new();
        for dir in urdf_dir.ancestors().take(4) {
            for candidate in [dir.join(package).join(path), dir.join(path)] {
                if candidate.is_file() {
                    return Ok(candidate);
                }
                tried.push(candidate);
            }
        }
        return Err(not_found(&tried));
    }
    let path = urdf_dir.join(filename.strip_prefix("file://").unwrap_or(filename));
    if path.is_file() { Ok(path) } else { Err(not_found(&[path])) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_meshes_are_typed_errors() {
        for text in [
            "",
            "v 0 0 0\n",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
            "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n",
            "v 0 0 0\nv 1 0 0\nf 1 2\n",
        ] {
            assert!(matches!(Mesh::parse_obj(text), Err(RobotError::Mesh { .. })), "{text:?}");
        }
        // Texture indices counted back before the first are passed over: only positions count.
        let degenerate = Mesh::parse_obj("v 0 0 0\nvt 0 0\nf 1/-3 1/1 1/1\n").unwrap();
        assert_eq!(degenerate.triangles, [[0, 0, 0]]);
        // A binary STL claiming four billion triangles, in 84 bytes.
        let mut stl = vec![0u8; 80];
        stl.extend(u32::MAX.to_le_bytes());
        assert!(matches!(Mesh::parse_stl(&stl), Err(RobotError::TooLarge { .. })));
        let mut short = vec![0u8; 80];
        short.extend(2u32.to_le_bytes());
        assert!(matches!(Mesh::parse_stl(&short), Err(RobotError::Mesh { .. })));
    }

    #[test]
    fn stl_binary_and_ascii_read_the_same_triangle() {
        let ascii = b"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
        let mut binary = vec![0u8; 80];
        binary.extend(1u32.to_le_bytes());
        for v in [[0f32, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]] {
            binary.extend(v.iter().flat_map(|x| x.to_le_bytes()));
        }
        binary.extend([0u8; 2]);
        let (a, b) = (Mesh::parse_stl(ascii).unwrap(), Mesh::parse_stl(&binary).unwrap());
        assert_eq!(a, b);
        assert_eq!(a.triangles.len(), 1);
        assert_eq!(a.radius(), 1.0);
    }
}
