//! The planner object of a document: every planner of the registry with its settings.

use arbitrary::{Result, Unstructured};
use serde_json::{Map, Value, json};
use trailmark::solve::PlannerName;

use super::*;

/// An optional heuristic, mostly admissible ones.
pub(super) fn heuristic(u: &mut Unstructured, grid: bool) -> Result<Option<Value>> {
    maybe(u, 96, |u| {
        Ok(json!(if grid {
            *u.choose(&["zero", "octile", "euclidean", "manhattan"])?
        } else {
            *u.choose(&["euclidean", "euclidean", "euclidean", "octile"])?
        }))
    })
}

/// A planner object with its parameters.
pub(super) fn planner_spec(u: &mut Unstructured, planner: PlannerName, grid: bool) -> Result<Value> {
    let mut spec = Map::new();
    spec.insert("name".into(), json!(planner.name()));
    match planner {
        PlannerName::Bfs
        | PlannerName::Dfs
        | PlannerName::Dijkstra
        | PlannerName::ThetaStar
        | PlannerName::Jps
        | PlannerName::JpsPlus => {}
        PlannerName::AStar
        | PlannerName::LpaStar
        | PlannerName::DStarLite
        | PlannerName::AdaptiveAStar
        | PlannerName::MpgaaStar => {
            insert(&mut spec, "heuristic", heuristic(u, grid)?);
        }
        PlannerName::WeightedAStar => {
            spec.insert("weight".into(), num(float(u, 1.0, 6.0)?));
            insert(&mut spec, "heuristic", heuristic(u, grid)?);
        }
        PlannerName::AraStar | PlannerName::AdStar => {
            insert(&mut spec, "epsilon", maybe(u, 192, |u| float(u, 1.0, 8.0).map(num))?);
            insert(&mut spec, "epsilon_step", maybe(u, 192, |u| float(u, 0.0, 2.0).map(num))?);
            insert(&mut spec, "heuristic", heuristic(u, grid)?);
            insert(&mut spec, "time_limit_s", maybe(u, 64, |u| float(u, 0.0, 0.25).map(num))?);
            insert(
                &mut spec,
                "max_expansions",
                maybe(u, 96, |u| {
                    Ok(json!(if u.ratio(1u8, 3)? { hostile_u64(u)? } else { u.int_in_range(0..=200)? }))
                })?,
            );
        }
        PlannerName::HybridAStar => {
            // Built with its world by hybrid_problem; a plain one here.
            spec.insert("turning_radius".into(), json!(1.0));
            spec.insert("max_expansions".into(), json!(100));
        }
        PlannerName::Rrt
        | PlannerName::RrtConnect
        | PlannerName::RrtStar
        | PlannerName::InformedRrtStar
        | PlannerName::BitStar
        | PlannerName::Prm
        | PlannerName::PrmStar
        | PlannerName::LazyPrm
        | PlannerName::LazyPrmStar => {
            // The roadmaps and BIT* refuse a range and a goal bias: given now and then, to reach the error.
            let roadmap = matches!(
                planner,
                PlannerName::Prm
                    | PlannerName::PrmStar
                    | PlannerName::LazyPrm
                    | PlannerName::LazyPrmStar
                    | PlannerName::BitStar
            );
            let p = if roadmap { 8 } else { 128 };
            insert(&mut spec, "range", maybe(u, p, |u| float(u, 0.0, 4.0).map(num))?);
            insert(&mut spec, "goal_bias", maybe(u, p, |u| float(u, 0.0, 1.0).map(num))?);
            let iterations = match planner {
                PlannerName::RrtStar
                | PlannerName::InformedRrtStar
                | PlannerName::BitStar
                | PlannerName::PrmStar
                | PlannerName::LazyPrmStar => 600,
                _ => 2000,
            };
            spec.insert("max_iterations".into(), json!(u.int_in_range(0..=iterations)?));
            insert(&mut spec, "time_limit_s", maybe(u, 48, |u| hostile_f64(u).map(num))?);
            insert(&mut spec, "simplify", maybe(u, 128, |u| u.arbitrary::<bool>().map(|b| json!(b)))?);
            insert(
                &mut spec,
                "smooth",
                maybe(u, 64, |u| Ok(json!(*u.choose(&["hermite", "bezier", "bspline"])?)))?,
            );
            insert(&mut spec, "sampler", maybe(u, 128, sampler)?);
        }
    }
    Ok(Value::Object(spec))
}

/// A sampler object of a sampling planner.
pub(super) fn sampler(u: &mut Unstructured) -> Result<Value> {
    let name = *u.choose(&["uniform", "bridge", "gaussian"])?;
    let mut spec = Map::new();
    spec.insert("name".into(), json!(name));
    if name != "uniform" {
        spec.insert("std_dev".into(), num(float(u, 0.0, 2.0)?));
        insert(&mut spec, "share", maybe(u, 128, |u| float(u, 0.0, 1.0).map(num))?);
        insert(&mut spec, "attempts", maybe(u, 128, |u| Ok(json!(*u.choose(&[0u32, 1, 2, 10, 50, 100])?)))?);
    }
    Ok(Value::Object(spec))
}
