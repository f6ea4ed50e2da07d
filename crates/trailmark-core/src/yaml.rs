//! YAML documents read safely: the shapes no robot file uses and an attacker would (anchors and
//! aliases, which expand without bound; deep nesting) are refused from the text's events, before
//! any document is built. ROS map files and MoveIt scenes and requests are read through it.
//!
//! ```
//! use trailmark_core::yaml;
//!
//! let doc = yaml::load("a: [1, 2]\n", "map files")?;
//! assert_eq!(doc["a"][1].as_i64(), Some(2));
//! assert!(yaml::load("a: &x [1]\nb: *x\n", "map files").is_err());
//! # Ok::<(), String>(())
//! ```

pub use yaml_rust2::Yaml;
use yaml_rust2::YamlLoader;
use yaml_rust2::parser::{Event, Parser};

/// The deepest lists and mappings may nest.
pub const MAX_DEPTH: usize = 16;

/// The first document of `text`, after [`screen`]; `files` names the kind of file in messages
/// (`"map files"`). Errors with the reason, and the line and column where it applies.
pub fn load(text: &str, files: &str) -> Result<Yaml, String> {
    screen(text, files)?;
    let docs = YamlLoader::load_from_str(text).map_err(|e| e.to_string())?;
    docs.into_iter().next().ok_or_else(|| "the file is empty".to_string())
}

/// Refuses anchors (`&name`), aliases (`*name`) and lists or mappings nested deeper than
/// [`MAX_DEPTH`], reading the parser's events one at a time (the parser keeps its nesting on the
/// heap). The loader copies an anchored node wherever an alias names it, so a few hundred bytes
/// of aliases naming aliases expand to billions of nodes; and a deeply nested document is
/// dropped by recursion deeper than a thread's stack.
pub fn screen(text: &str, files: &str) -> Result<(), String> {
    let mut parser = Parser::new_from_str(text);
    let mut depth = 0usize;
    loop {
        let (event, mark) = parser.next_token().map_err(|e| e.to_string())?;
        let refuse = |what: &str, why: &str| {
            let (line, column) = (mark.line(), mark.col() + 1);
            Err(format!("{what} at line {line} column {column}: {why}"))
        };
        let no_aliases = format!("{files} use no anchors or aliases");
        let anchor = match &event {
            Event::Scalar(_, _, anchor, _)
            | Event::SequenceStart(anchor, _)
            | Event::MappingStart(anchor, _) => *anchor,
            _ => 0,
        };
        // The parser numbers anchors from 1; 0 is a node without one.
        if anchor != 0 {
            return refuse("an anchor (`&name`)", &no_aliases);
        }
        match event {
            Event::StreamEnd => return Ok(()),
            Event::Alias(_) => return refuse("an alias (`*name`)", &no_aliases),
            Event::SequenceStart(..) | Event::MappingStart(..) => {
                depth += 1;
                if depth > MAX_DEPTH {
                    let why = format!("lists and mappings nest at most {MAX_DEPTH} deep");
                    return refuse("a list or mapping", &why);
                }
            }
            Event::SequenceEnd | Event::MappingEnd => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
}

/// A number, integer or real, as `f64`.
pub fn number(value: &Yaml) -> Option<f64> {
    match value {
        Yaml::Integer(i) => Some(*i as f64),
        Yaml::Real(_) => value.as_f64(),
        _ => None,
    }
}
