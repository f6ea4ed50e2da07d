//! Valid-shaped problem documents with hostile values, for the `solve_document` target.
//!
//! [`ProblemDoc`] implements [`Arbitrary`]: from the fuzzer's bytes it builds the JSON of a
//! problem in the schema of trailmark-core's `problem.rs` — a small grid (inline rows, optional
//! costs) or a polygon world of a few polygons, any planner of the registry (`trailmark::solve::PlannerName::ALL`), any roadmap, space
//! and sampler — whose numbers are mostly ordinary and otherwise extreme: 0, -0, 1e308, 1e-300,
//! the smallest subnormal, `u32::MAX`, `u64::MAX`, values just beyond a documented limit. The
//! parameters that bound the work (samples, iterations, time limits, sampler attempts) stay
//! small; the bytes decide everything else. Most documents are valid, so the planners run;
//! a tenth or so put a field where it does not belong, to reach the errors.
//!
//! Hybrid A* documents (issue 47) plan on grids (cells 0.05 to 10 m wide and coarser, sometimes
//! a row or column a million or a trillion times dearer than the rest, or that row alone open)
//! and polygon worlds, with footprints about the reference point, ahead of it (not holding it),
//! sharp thin triangles, rings past the 1024 vertices documented, hostile coordinates, and
//! small expansion or time limits. Box worlds sometimes hold touching boxes: a box cut in two,
//! two boxes meeting at a corner, a wall of boxes with the ends on its two sides.

use std::fmt;

use arbitrary::{Arbitrary, Result, Unstructured};
use serde_json::{Map, Value, json};
use trailmark::solve::{Family, PlannerName};

mod boxes;
mod car;
mod grid;
mod planner;
mod polygons;
mod values;

use boxes::*;
use car::*;
use grid::*;
use planner::*;
use polygons::*;
pub use values::hostile_f64;
use values::*;

/// A problem document, as JSON. Its `Debug` form is the JSON text, so that a crash report
/// (`cargo fuzz fmt`) shows the document.
pub struct ProblemDoc(pub Value);

impl fmt::Debug for ProblemDoc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&serde_json::to_string(&self.0).unwrap_or_default())
    }
}

impl<'a> Arbitrary<'a> for ProblemDoc {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        problem(u).map(ProblemDoc)
    }
}

/// The roadmaps of polygon worlds (`None`: the default, visibility).
#[derive(Arbitrary, Debug, Clone, Copy, PartialEq, Eq)]
pub enum GraphName {
    Default,
    Visibility,
    Trapezoid,
    Prm,
    DubinsPrm,
    ReedsSheppPrm,
}

/// A whole problem document.
pub fn problem(u: &mut Unstructured) -> Result<Value> {
    let grid = u.ratio(1u8, 2)?;
    let misplaced = u.ratio(1u8, 10)?;
    // Every planner of the registry, drawn from its own list.
    let mut planner: PlannerName = *u.choose(PlannerName::ALL)?;
    // Sampling planners take polygon worlds; a few mismatched pairs reach the error.
    if grid && planner.family() == Family::Sampling && !misplaced {
        planner = PlannerName::AStar;
    }
    // Hybrid A* more often than one planner in eighteen: its documents have the most shapes.
    if u.ratio(1u8, 16)? {
        planner = PlannerName::HybridAStar;
    }
    let mut doc = Map::new();
    if planner == PlannerName::HybridAStar {
        hybrid_problem(u, &mut doc, grid)?;
    } else if !grid && planner.family() == Family::Sampling && u.ratio(1u8, 4)? {
        box_world(u, &mut doc)?;
    } else if grid {
        let (world, width, height) = grid_world(u)?;
        doc.insert("world".into(), world);
        doc.insert("start".into(), grid_end(u, width, height)?);
        doc.insert("goal".into(), grid_end(u, width, height)?);
    } else {
        let (world, frame) = polygon_world(u)?;
        let graph: GraphName = u.arbitrary()?;
        let space_dubins = planner.family() == Family::Sampling && u.ratio(1u8, 3)?;
        let car_roadmap = matches!(graph, GraphName::DubinsPrm | GraphName::ReedsSheppPrm);
        let dubins = space_dubins || (planner.family() != Family::Sampling && car_roadmap);
        doc.insert("world".into(), world);
        doc.insert("start".into(), polygon_end(u, &frame, dubins)?);
        doc.insert("goal".into(), polygon_end(u, &frame, dubins)?);
        if dubins || misplaced && u.ratio(1u8, 2)? {
            doc.insert("turning_radius".into(), num(float(u, 0.0, 3.0)? * frame.scale));
        }
        if planner.family() == Family::Sampling {
            if space_dubins || misplaced && u.ratio(1u8, 2)? {
                let car = if u.ratio(1u8, 2)? { "dubins" } else { "reeds_shepp" };
                doc.insert("space".into(), json!(if space_dubins { car } else { "r2" }));
            } else if u.ratio(1u8, 4)? {
                doc.insert("space".into(), json!("r2"));
            }
        } else {
            roadmap_fields(u, &mut doc, graph, &frame)?;
        }
    }
    if misplaced {
        // A field of the other kind of world or planner.
        match u.int_in_range(0u8..=4)? {
            0 => doc.insert("samples".into(), json!(u.int_in_range(0u32..=50)?)),
            1 => doc.insert("graph".into(), json!("prm")),
            2 => doc.insert("space".into(), json!("dubins")),
            3 => doc.insert("k".into(), json!(hostile_u64(u)?)),
            _ => doc.insert("sampler".into(), json!("halton")),
        };
    }
    if u.ratio(1u8, 2)? {
        doc.insert("seed".into(), json!(hostile_u64(u)?));
    }
    if planner != PlannerName::HybridAStar {
        doc.insert("planner".into(), planner_spec(u, planner, grid)?);
    }
    Ok(Value::Object(doc))
}

#[cfg(test)]
mod tests {
    use super::*;
    use trailmark::solve::{ProblemSpec, Status};

    /// Most generated documents parse, and a fair share of them are solved: the generator
    /// reaches the planners rather than only the input checks. Prints the tally
    /// (`cargo test --release -- --nocapture` in fuzz/).
    #[test]
    fn documents_reach_the_planners() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut tally = std::collections::BTreeMap::<String, usize>::new();
        let n = 600;
        for _ in 0..n {
            let bytes = pseudo_random_bytes(&mut state, 512);
            let doc = problem(&mut Unstructured::new(&bytes)).unwrap();
            let outcome = match serde_json::from_value::<ProblemSpec>(doc) {
                Err(e) => format!("not a problem: {}", e.to_string().chars().take(60).collect::<String>()),
                Ok(p) if !crate::budget::problem_is_quick(&p) => "skipped".to_string(),
                Ok(p) => match trailmark::solve::solve(&p, crate::NO_DIR) {
                    Err(e) => format!("error: {}", e.to_string().chars().take(60).collect::<String>()),
                    Ok(r) => format!("{}: {:?}", p.planner.name(), r.status),
                },
            };
            *tally.entry(outcome).or_default() += 1;
        }
        for (outcome, count) in &tally {
            println!("{count:5} {outcome}");
        }
        let solved: usize =
            tally.iter().filter(|(k, _)| k.ends_with(&format!("{:?}", Status::Solved))).map(|(_, v)| v).sum();
        // A sixth: Hybrid A* documents, an eighth of all, are mostly refused or stopped by design
        // (footprints off the map or over obstacles, hostile settings, tiny limits).
        assert!(solved * 6 >= n, "only {solved} of {n} documents solved");
    }

    /// `len` bytes of a xorshift generator from `state`, which it advances.
    fn pseudo_random_bytes(state: &mut u64, len: usize) -> Vec<u8> {
        (0..len)
            .map(|_| {
                *state ^= *state << 13;
                *state ^= *state >> 7;
                *state ^= *state << 17;
                *state as u8
            })
            .collect()
    }

    /// `n` documents made by `make` from pseudo-random bytes.
    fn documents(
        n: usize,
        make: impl Fn(&mut Unstructured, &mut Map<String, Value>) -> Result<()>,
    ) -> Vec<Value> {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        (0..n)
            .map(|_| {
                let bytes = pseudo_random_bytes(&mut state, 1024);
                let mut doc = Map::new();
                make(&mut Unstructured::new(&bytes), &mut doc).unwrap();
                Value::Object(doc)
            })
            .collect()
    }

    /// Documents made by `make`, each run through the checks; the tally of their outcomes (a
    /// status and stop, an error's start, skipped).
    fn run_documents(
        n: usize,
        make: impl Fn(&mut Unstructured, &mut Map<String, Value>) -> Result<()>,
    ) -> std::collections::BTreeMap<String, usize> {
        let mut tally = std::collections::BTreeMap::<String, usize>::new();
        for doc in documents(n, make) {
            let outcome = match serde_json::from_value::<ProblemSpec>(doc.clone()) {
                Err(e) => format!("not a problem: {}", e.to_string().chars().take(50).collect::<String>()),
                Ok(p) if !crate::budget::problem_is_quick(&p) => "skipped".to_string(),
                Ok(p) => {
                    let outcome = match trailmark::solve::solve(&p, crate::NO_DIR) {
                        Err(e) => format!("error: {}", e.to_string().chars().take(80).collect::<String>()),
                        Ok(r) => format!("{:?} {:?}", r.status, r.stats.stop),
                    };
                    if std::panic::catch_unwind(|| crate::solve_and_check(&p)).is_err() {
                        panic!("a check failed on {doc}");
                    }
                    outcome
                }
            };
            *tally.entry(outcome).or_default() += 1;
        }
        for (outcome, count) in &tally {
            println!("{count:5} {outcome}");
        }
        tally
    }

    fn count(tally: &std::collections::BTreeMap<String, usize>, prefix: &str) -> usize {
        tally.iter().filter(|(k, _)| k.starts_with(prefix)).map(|(_, v)| v).sum()
    }

    /// Hybrid A* documents on grids and polygon worlds pass the checks, and enough of them are
    /// solved, stopped, proved unreachable and refused for too many footprint vertices.
    #[test]
    fn hybrid_documents_are_solved_and_checked() {
        for grid in [true, false] {
            println!("hybrid_astar on {} worlds:", if grid { "grid" } else { "polygon" });
            let tally = run_documents(300, |u, doc| hybrid_problem(u, doc, grid));
            let solved = count(&tally, "Solved");
            assert!(
                solved >= if grid { 25 } else { 12 },
                "{} world: only {solved} of 300 solved",
                if grid { "grid" } else { "polygon" }
            );
            assert!(count(&tally, "Stopped") >= 10);
            assert!(count(&tally, "error: the footprint: a footprint polygon has at most") >= 3);
            if grid {
                assert!(count(&tally, "NoPath") >= 3);
            }
        }
    }

    /// Box worlds, touching boxes and walls among them, pass the checks; walls between the
    /// ends are generated, found by the check, and never crossed.
    #[test]
    fn box_documents_are_checked() {
        let tally = run_documents(300, box_world_with_planner);
        assert!(count(&tally, "Solved") + count(&tally, "Approximate") >= 60);
        let mut parted = 0;
        for doc in documents(300, box_world_with_planner) {
            let Ok(p) = serde_json::from_value::<ProblemSpec>(doc) else { continue };
            let trailmark::solve::WorldSpec::Boxes(world) = &p.world else { unreachable!() };
            let Ok(result) = trailmark::solve::solve(&p, crate::NO_DIR) else { continue };
            let parts = |(axis, c0, c1): (usize, f64, f64)| {
                let (s, g) = (p.start[axis], p.goal[axis]);
                (s < c0 && g > c1) || (s > c1 && g < c0)
            };
            if crate::boxes::walls(world).into_iter().any(parts) {
                parted += 1;
                assert_ne!(result.status, Status::Solved, "solved across a wall");
            }
        }
        println!("{parted} documents with a wall between the ends");
        assert!(parted >= 15, "only {parted} documents with a wall between the ends");
    }

    /// A box world and an RRT-Connect planner with a small iteration limit.
    fn box_world_with_planner(u: &mut Unstructured, doc: &mut Map<String, Value>) -> Result<()> {
        box_world(u, doc)?;
        doc.insert("planner".into(), json!({"name": "rrt_connect", "max_iterations": 500}));
        Ok(())
    }
}
