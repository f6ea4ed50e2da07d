//! Draws the figures of the guide (`docs/img/*.svg`) from seeded, generated worlds, so they can
//! be remade on any machine: `cargo run --release --example figures`.

use std::path::Path;

use trailmark::core::generate;
use trailmark::navigate::{Navigation, Target, navigate_together};
use trailmark::prelude::*;
use trailmark::solve::PlannerSpec;
use trailmark::svg::GridSvg;

fn write(name: &str, svg: String) -> std::io::Result<()> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/img");
    std::fs::create_dir_all(&dir)?;
    std::fs::write(dir.join(name), svg)?;
    println!("wrote docs/img/{name}");
    Ok(())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // trailmark-core: a cost grid (a costly band across rooms) with blocked walls.
    let mut grid = generate::rooms(64, 40, 9, 4)?;
    for y in 0..40 {
        for x in 26..38 {
            let cell = Cell::new(x, y);
            if grid.is_passable(cell) {
                grid.set_cost(cell, 1.0 + f64::from(12 - (x as i32 - 32).unsigned_abs().min(6) * 2) / 3.0)?;
            }
        }
    }
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let (start, goal) = (Cell::new(1, 20), Cell::new(62, 18));
    let path =
        astar(&graph, start, goal, graph.heuristic(GridHeuristic::Octile, goal))?.path.ok_or("no path")?;
    write(
        "core-cost-grid.svg",
        GridSvg::new(&grid)
            .cell_size(10.0)
            .title("A cost grid: walls, a costly band, a least-cost path")
            .path(&path.nodes)
            .to_svg(),
    )?;

    // trailmark-graph: the same query under 4-connectivity, 8 without and with corner cutting.
    let grid = generate::random(40, 24, 0.22, 11)?;
    let (start, goal) = (Cell::new(0, 3), Cell::new(39, 20));
    let mut picture = GridSvg::new(&grid)
        .cell_size(14.0)
        .title("4-connected, 8-connected, 8-connected squeezing between corners");
    for (connectivity, rule) in [
        (Connectivity::Four, CornerCutting::Forbidden),
        (Connectivity::Eight, CornerCutting::Forbidden),
        (Connectivity::Eight, CornerCutting::Squeeze),
    ] {
        let graph = GridGraph::new(&grid, connectivity).with_corner_cutting(rule);
        if let Some(path) = dijkstra(&graph, start, goal)?.path {
            println!("{connectivity:?} {rule:?}: cost {:.3}, {} moves", path.cost, path.moves());
            picture = picture.path(&path.nodes);
        }
    }
    write("graph-connectivity.svg", picture.to_svg())?;

    // trailmark-search: what Dijkstra, A* and weighted A* expand for the same query.
    let grid = generate::rooms(96, 64, 11, 2)?;
    let graph = GridGraph::new(&grid, Connectivity::Eight);
    let (start, goal) = (Cell::new(2, 60), Cell::new(93, 3));
    let h = graph.heuristic(GridHeuristic::Octile, goal);
    let mut search = Search::new();
    for (name, label) in
        [("dijkstra", "Dijkstra"), ("astar", "A*"), ("weighted-astar", "weighted A* (w = 2)")]
    {
        let found = match name {
            "dijkstra" => search.dijkstra(&graph, start, goal)?,
            "astar" => search.astar(&graph, start, goal, h)?,
            _ => search.weighted_astar(&graph, start, goal, h, 2.0)?,
        };
        let path = found.path.ok_or("no path")?;
        let title = format!("{label}: {} expansions, cost {:.2}", found.stats.expansions, path.cost);
        println!("{title}");
        let svg = GridSvg::new(&grid)
            .cell_size(5.0)
            .title(title)
            .explored(search.expanded(&graph))
            .path(&path.nodes);
        write(&format!("search-{name}.svg"), svg.to_svg())?;
    }
    // Jump point search on the same query: only the cells where a path may turn are expanded.
    let mut jps = Jps::new(&grid, CornerCutting::Forbidden)?;
    let found = jps.search(start, goal)?;
    let path = found.path.ok_or("no path")?;
    let title = format!("Jump point search: {} expansions, cost {:.2}", found.stats.expansions, path.cost);
    println!("{title}");
    let svg = GridSvg::new(&grid).cell_size(5.0).title(title).explored(jps.expanded()).path(&path.nodes);
    write("search-jps.svg", svg.to_svg())?;

    // Navigation in unknown terrain: a robot with a free-space prior and a sensor radius of 3,
    // driven by D* Lite, with A* from scratch planning along the same trajectory for comparison.
    let truth = generate::rooms(96, 64, 15, 5)?;
    let prior = Grid::new(96, 64)?;
    let (start, goal) = (Cell::new(2, 61), Cell::new(93, 2));
    let config = Navigation {
        planner: PlannerSpec::DStarLite { heuristic: None },
        sensor_radius: 3,
        ..Navigation::default()
    };
    let runs = navigate_together(
        &truth,
        &prior,
        start,
        Target::Cell(goal),
        &config,
        &[PlannerSpec::AStar { heuristic: None }],
    )?;
    let (dstar, scratch) = (&runs[0], &runs[1]);
    println!(
        "navigation: {:?} in {} steps; D* Lite {} expansions, A* from scratch {}",
        dstar.outcome, dstar.steps, dstar.expansions, scratch.expansions
    );
    write("navigate-dstar-lite.svg", dstar.svg(&truth, Some(goal)))?;

    write("core-dubins.svg", dubins_words()?)?;
    write("core-reeds-shepp.svg", reeds_shepp_parking()?)?;
    roadmaps()?;
    write("graph-lazy-visibility.svg", lazy_visibility()?)?;
    bridge_samples()?;
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    ros_map(&root.join("examples/maps/office.yaml"), "map-office.svg", [-4.2, -2.2], [4.3, 2.3])?;
    let warehouse = root.join("../shared/rosmaps/warehouse.yaml");
    if warehouse.is_file() {
        ros_map(&warehouse, "map-warehouse.svg", [-12.0, -20.0], [10.0, 15.0])?;
    } else {
        println!("skipped docs/img/map-warehouse.svg: {} not found", warehouse.display());
    }
    write("car-polygon-lot.svg", car_lot()?)?;
    let depot = root.join("../shared/rosmaps/depot.yaml");
    if depot.is_file() {
        write("car-hybrid-astar.svg", car_parking(&depot)?)?;
    } else {
        println!("skipped docs/img/car-hybrid-astar.svg: {} not found", depot.display());
    }
    Ok(())
}

/// Hybrid A* backing a 0.6 m x 0.4 m car into the gap between two pallet stacks of Nav2's depot
/// map: the path forward in blue, in reverse in orange, the footprint every 0.4 m, the cusps in
/// red.
fn car_parking(yaml: &Path) -> Result<String, Box<dyn std::error::Error>> {
    use std::fmt::Write as _;
    use trailmark::car::{CarMap, HybridAStar, HybridOptions};
    use trailmark::core::footprint::Footprint;
    use trailmark::core::geometry::{Point, Pose, Vector};
    use trailmark::core::reeds_shepp::Gear;
    use trailmark::core::termination::Termination;
    use trailmark::core::world::Polygon;
    use trailmark::map::{Costmap, CostmapOptions, CostmapSvg, Inflation, load_map};
    let corners = [(-0.15, -0.2), (0.45, -0.2), (0.45, 0.2), (-0.15, 0.2)];
    let car = Footprint::Polygon(Polygon::new(corners.iter().map(|&(x, y)| Point::new(x, y)).collect())?);
    let settings = CostmapOptions { inflation: Some(Inflation::around(&car)?), ..CostmapOptions::default() };
    let costmap = Costmap::from_occupancy(&load_map(yaml)?, &settings)?;
    let map = CarMap::from_costmap(&costmap, &Default::default())?;
    let planner =
        HybridAStar::new(&map, &car, HybridOptions { turning_radius: 0.5, ..HybridOptions::default() })?;
    let start = Pose::new(Vector::new(13.0, 8.5), 0.0);
    let goal = Pose::new(Vector::new(19.7, 3.1), std::f64::consts::FRAC_PI_2);
    let plan = planner.plan(&start, &goal, &Termination::unlimited())?;
    let path = &plan.path;
    println!(
        "depot parking: {:.2} m, {} cusps, {} expansions, {:.1} ms",
        path.length(),
        path.cusps().len(),
        plan.stats.expansions,
        plan.stats.time.as_secs_f64() * 1e3
    );
    let frame = *costmap.frame();
    let grid = |p: Point| frame.point_to_grid(p);
    let mut extra = String::new();
    // The footprint every 0.4 m of travel, and at the cusps.
    let dense = path.sample(0.02);
    let mut travelled = 0.0;
    let mut shown = Vec::new();
    for pair in dense.windows(2) {
        travelled += (pair[1].0.translation.vector - pair[0].0.translation.vector).norm();
        if travelled >= 0.4 || pair[0].1 != pair[1].1 {
            shown.push(pair[0].0);
            travelled = 0.0;
        }
    }
    shown.push(goal);
    for stretch in &path.stretches {
        let points: Vec<String> = (0..=8)
            .map(|i| {
                let (gx, gy) = grid(Point::from(
                    stretch
                        .pose_at(stretch.length * f64::from(i) / 8.0, path.turning_radius)
                        .translation
                        .vector,
                ));
                format!("{gx:.2},{gy:.2}")
            })
            .collect();
        let colour = if stretch.gear == Gear::Forward { "#0b62d6" } else { "#e67e22" };
        let _ = writeln!(
            extra,
            r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="0.9" stroke-linecap="round"/>"#,
            points.join(" ")
        );
    }
    let mut picture = CostmapSvg::new(&costmap).pixels_per_cell(2.0);
    for pose in &shown {
        picture = picture.outline(&car.corners_at(pose));
    }
    for cusp in path.cusps() {
        picture = picture.mark(Point::from(cusp.translation.vector));
    }
    let svg = picture
        .start(Point::from(start.translation.vector))
        .goal(Point::from(goal.translation.vector))
        .title(format!(
            "Hybrid A* on Nav2's depot map: a 0.6 m x 0.4 m car, turning radius 0.5 m, backs into a gap; \
             forward (blue), reverse (orange), cusps (red); {:.1} m",
            path.length()
        ))
        .to_svg()?;
    // Only the part of the map around the path: 40 cells beyond it on every side.
    let (mut lo, mut hi) = ((f64::INFINITY, f64::INFINITY), (f64::NEG_INFINITY, f64::NEG_INFINITY));
    for (pose, _) in &dense {
        let (x, y) = grid(Point::from(pose.translation.vector));
        lo = (lo.0.min(x - 40.0), lo.1.min(y - 40.0));
        hi = (hi.0.max(x + 40.0), hi.1.max(y + 40.0));
    }
    let (w, h) = (frame.width(), frame.height());
    let whole = format!(r#"width="{}" height="{}" viewBox="0 0 {w} {h}""#, 2 * w, 2 * h);
    let part = format!(
        r#"width="{:.0}" height="{:.0}" viewBox="{:.1} {:.1} {:.1} {:.1}""#,
        4.0 * (hi.0 - lo.0),
        4.0 * (hi.1 - lo.1),
        lo.0,
        lo.1,
        hi.0 - lo.0,
        hi.1 - lo.1
    );
    Ok(svg.replace(&whole, &part).replace("</svg>\n", &format!("{extra}</svg>\n")))
}

/// Hybrid A* parking a 1.2 m x 0.8 m car between two parked ones in a polygon world, the world
/// laid on cells of an eighth of the turning radius: the path, the footprint every 0.5 m, the
/// cusps in red.
fn car_lot() -> Result<String, Box<dyn std::error::Error>> {
    use std::f64::consts::FRAC_PI_2;
    use trailmark::car::{CarMap, HybridAStar, HybridOptions};
    use trailmark::core::footprint::Footprint;
    use trailmark::core::geometry::{Point, Pose, Vector};
    use trailmark::core::svg::WorldSvg;
    use trailmark::core::termination::Termination;
    use trailmark::core::world::{Bounds, Polygon, PolygonWorld};
    let rect = |x0: f64, y0: f64, x1: f64, y1: f64| {
        vec![Point::new(x0, y0), Point::new(x1, y0), Point::new(x1, y1), Point::new(x0, y1)]
    };
    let obstacles = vec![rect(1.0, 0.5, 5.0, 2.3), rect(7.4, 0.5, 11.0, 2.3), rect(3.0, 6.5, 9.0, 7.5)];
    let world = PolygonWorld::new(Bounds::new(0.0, 0.0, 12.0, 8.0)?, obstacles, 0.0)?;
    let corners = [(-0.2, -0.4), (1.0, -0.4), (1.0, 0.4), (-0.2, 0.4)];
    let car = Footprint::Polygon(Polygon::new(corners.iter().map(|&(x, y)| Point::new(x, y)).collect())?);
    let settings = HybridOptions { turning_radius: 1.2, ..HybridOptions::default() };
    let map = CarMap::from_world(&world, settings.turning_radius / 8.0)?;
    let planner = HybridAStar::new(&map, &car, settings)?;
    let (start, goal) = (Pose::new(Vector::new(2.0, 5.0), 0.0), Pose::new(Vector::new(6.2, 1.2), FRAC_PI_2));
    let plan = planner.plan(&start, &goal, &Termination::unlimited())?;
    let path = &plan.path;
    println!(
        "polygon lot: {:.2} m, {} cusps, {} expansions, {:.1} ms",
        path.length(),
        path.cusps().len(),
        plan.stats.expansions,
        plan.stats.time.as_secs_f64() * 1e3
    );
    let dense = path.sample(0.02);
    let points: Vec<Point> = dense.iter().map(|(p, _)| Point::from(p.translation.vector)).collect();
    let mut picture = WorldSvg::new(&world).scale(60.0).path(&points);
    let mut travelled = f64::INFINITY;
    for pair in dense.windows(2) {
        if travelled >= 0.5 {
            picture = picture.outline(&car.corners_at(&pair[0].0));
            travelled = 0.0;
        }
        travelled += (pair[1].0.translation.vector - pair[0].0.translation.vector).norm();
    }
    picture = picture.outline(&car.corners_at(&goal));
    for cusp in path.cusps() {
        picture = picture.outline(&car.corners_at(&cusp)).mark(Point::from(cusp.translation.vector));
    }
    Ok(picture
        .start(Point::from(start.translation.vector))
        .goal(Point::from(goal.translation.vector))
        .title(format!("Hybrid A* parking a 1.2 m x 0.8 m car between polygons: {:.1} m", path.length()))
        .to_svg())
}

/// A ROS map made a costmap around a 0.2 m robot, with A* (blue), A* shortcut (green) and
/// Theta* (orange) from `start` to `goal` in metres.
fn ros_map(
    yaml: &Path,
    name: &str,
    start: [f64; 2],
    goal: [f64; 2],
) -> Result<(), Box<dyn std::error::Error>> {
    use trailmark::core::geometry::Point;
    use trailmark::map::CostmapSvg;
    use trailmark::search::theta_star;
    use trailmark::solve::{RosMapSpec, ros_costmap, ros_travel_cost};
    let spec: RosMapSpec = serde_json::from_value(serde_json::json!({
        "yaml": yaml, "robot_radius": 0.2, "inflation_radius": 0.55, "cost_scaling_factor": 10.0
    }))?;
    let costmap = ros_costmap(&spec, ".")?;
    let frame = *costmap.frame();
    let graph =
        GridGraph::new(&costmap.to_grid(&ros_travel_cost(&spec, frame.resolution()))?, Connectivity::Eight);
    let (s, g) = (frame.cell_at(Point::from(start))?, frame.cell_at(Point::from(goal))?);
    let grid_path = astar(&graph, s, g, graph.heuristic(GridHeuristic::Octile, g))?.path.ok_or("no path")?;
    let theta = theta_star(&graph, s, g, graph.heuristic(GridHeuristic::Euclidean, g), &graph)?
        .path
        .ok_or("no path")?;
    let short = graph.shortcut(&grid_path.nodes);
    let metres = |cells: &[Cell]| -> Vec<Point> { cells.iter().map(|&c| frame.centre(c)).collect() };
    let cost = |cells: &[Cell]| -> f64 { cells.windows(2).filter_map(|w| graph.line_cost(w[0], w[1])).sum() };
    println!(
        "{name}: A* {:.2}, A* shortcut {:.2}, Theta* {:.2} (cost, metres on free cells)",
        grid_path.cost,
        cost(&short),
        theta.cost
    );
    let svg = CostmapSvg::new(&costmap)
        .path(&metres(&grid_path.nodes))
        .path(&metres(&theta.nodes))
        .path(&metres(&short))
        .start(Point::from(start))
        .goal(Point::from(goal))
        .title(format!(
            "{}: costmap of a 0.2 m robot; A* (blue), Theta* (orange), A* shortcut (green)",
            yaml.file_stem().map_or(String::new(), |s| s.to_string_lossy().into_owned())
        ))
        .to_svg()?;
    Ok(write(name, svg)?)
}

/// The bridge-test sampler on the six-door world of the sampling benchmark: where its samples
/// fall, and an RRT-Connect path drawn with it.
fn bridge_samples() -> Result<(), Box<dyn std::error::Error>> {
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;
    use trailmark::core::geometry::Point;
    use trailmark::core::svg::WorldSvg;
    use trailmark::core::termination::Termination;
    use trailmark::sample::{Bridge, Draw, KdNearest, Planner, Problem, R2, RrtConnect, StateSampler};

    let world = generate::narrow_passages(40.0, 6, 1.5, 0.25, 2)?;
    let checker = world.checker();
    let space = R2::new(world.bounds());
    let (start, goal) = (Point::new(2.0, 8.0), Point::new(38.0, 33.0));
    let bridge = Bridge::new(2.0)?;
    let problem = Problem::new(&space, &checker, start, goal);
    let mut planner = RrtConnect::new(KdNearest::<R2, 2>::new(&space)?).with_sampler(&bridge).with_seed(1);
    let plan = planner.solve(&problem, &Termination::iterations(10_000))?;
    let path = plan.path().ok_or("no RRT-Connect path")?.to_vec();
    println!(
        "bridge: RRT-Connect {} iterations, {} checks, solved {}",
        plan.stats.iterations,
        plan.stats.collision_checks,
        plan.is_exact()
    );
    // 600 samples of the bridge test alone (every draw looks for a bridge).
    let only = Bridge::new(2.0)?.with_share(1.0)?.with_attempts(10_000)?;
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let mut checks = 0;
    let mut draw = Draw::new(&mut rng, &mut checks);
    let samples: Vec<Point> = (0..600).filter_map(|_| only.sample(&space, &checker, &mut draw)).collect();
    let svg = WorldSvg::new(&world)
        .free_space(&world.free_space())
        .nodes(samples)
        .path(&path)
        .start(start)
        .goal(goal)
        .title("Bridge test (std_dev 2): 600 samples, and RRT-Connect through six doors with it")
        .to_svg();
    Ok(write("sample-bridge.svg", svg)?)
}

/// One query among 144 unit squares by the lazy visibility graph: the edges its last round
/// swept, and the path.
fn lazy_visibility() -> Result<String, Box<dyn std::error::Error>> {
    use trailmark::core::geometry::Point;
    use trailmark::core::svg::WorldSvg;
    use trailmark::core::world::{Bounds, PolygonWorld};
    use trailmark::graph::{LazyVisibilityGraph, Roadmap};

    let k = 12;
    let side = (2 * k + 1) as f64;
    let square = |x: f64, y: f64| {
        vec![Point::new(x, y), Point::new(x + 1.0, y), Point::new(x + 1.0, y + 1.0), Point::new(x, y + 1.0)]
    };
    let obstacles = (0..k * k).map(|i| square((2 * (i % k) + 1) as f64, (2 * (i / k) + 1) as f64)).collect();
    let world = PolygonWorld::new(Bounds::new(0.0, 0.0, side, side)?, obstacles, 0.0)?;
    let graph = LazyVisibilityGraph::new(world.free_space());
    let (start, goal) = (Point::new(0.0, 0.0), Point::new(side, 0.3 * side));
    let mut bound = LazyVisibilityGraph::first_bound(start, goal);
    let (bounded, path) = loop {
        let bounded = graph.within(start, goal, bound)?;
        let q = bounded.query();
        let path = astar(&q, q.start(), q.goal(), q.heuristic())?.path;
        match bounded.next_bound(path.as_ref().map(|p| p.cost)) {
            Some(next) => bound = next,
            None => {
                let path = q.positions(&path.ok_or("no lazy visibility path")?.nodes);
                drop(q);
                break (bounded, path);
            }
        }
    };
    println!(
        "lazy visibility: {} nodes, {} swept, {} edges, bound {:.3}",
        graph.node_count(),
        bounded.swept(),
        bounded.count_edges(),
        bounded.bound()
    );
    let title = format!(
        "Lazy visibility graph: {} of {} corners swept, the edges they found, the shortest path",
        bounded.swept(),
        graph.node_count()
    );
    let svg = WorldSvg::new(&world)
        .free_space(graph.space())
        .edges(bounded.edge_ends())
        .path(&path)
        .start(start)
        .goal(goal)
        .title(title);
    Ok(svg.to_svg())
}

/// The four roadmap builders on one generated world (24 convex obstacles, robot radius 0.5)
/// with one start and goal: visibility graph, trapezoidal cells, PRM*, and a Dubins roadmap.
fn roadmaps() -> Result<(), Box<dyn std::error::Error>> {
    use trailmark::core::dubins::DubinsPath;
    use trailmark::core::geometry::{Point, Pose};
    use trailmark::core::svg::WorldSvg;
    use trailmark::graph::Roadmap;
    use trailmark::graph::trapezoid::Trapezoids;
    use trailmark::graph::visibility::{Edges, VisibilityGraph};
    use trailmark::sample::Dubins;
    use trailmark::sample::{Connection, PolygonPrm, PrmOptions, PrmSampler};

    let world = generate::convex_obstacles(40.0, 24, 6, 0.5, 7)?;
    // Round corners in quarter-turn steps keep the pictures small.
    let space = world.free_space_with_step(std::f64::consts::FRAC_PI_4)?;
    let (start, goal) = (Point::new(1.5, 20.0), Point::new(38.5, 38.0));

    let visibility = VisibilityGraph::with_edges(space.clone(), Edges::Tangent);
    let q = visibility.query(start, goal)?;
    let found = dijkstra(&q, q.start(), q.goal())?;
    let path = found.path.as_ref().ok_or("no visibility path")?;
    println!(
        "visibility: {} nodes, {} edges, cost {:.3}",
        visibility.node_count(),
        visibility.edge_count(),
        found.cost().unwrap_or(f64::NAN)
    );
    let svg = WorldSvg::new(&world)
        .free_space(&space)
        .edges(visibility.edge_ends())
        .path(&q.positions(&path.nodes))
        .start(start)
        .goal(goal)
        .title("Visibility graph (tangent edges): convex corners of the grown obstacles, the shortest path")
        .to_svg();
    write("graph-visibility.svg", svg)?;

    let cells = Trapezoids::new(&space);
    let q = cells.query(start, goal)?;
    let found = dijkstra(&q, q.start(), q.goal())?;
    let path = found.path.as_ref().ok_or("no trapezoid path")?;
    println!(
        "trapezoids: {} cells, {} portals, cost {:.3}",
        cells.cell_count(),
        cells.portals().len(),
        found.cost().unwrap_or(f64::NAN)
    );
    let svg = WorldSvg::new(&world)
        .free_space(&space)
        .cells((0..cells.cell_count()).map(|c| cells.cell(c).corners().to_vec()))
        .edges(cells.edge_ends())
        .path(&q.positions(&path.nodes))
        .start(start)
        .goal(goal)
        .title("Trapezoidal cells: centroids and portal midpoints, a path through the cells")
        .to_svg();
    write("graph-trapezoid.svg", svg)?;

    let options =
        PrmOptions { sampler: PrmSampler::Halton, connection: Connection::PrmStar, ..PrmOptions::default() };
    let mut prm = PolygonPrm::new(world.clone(), options)?;
    prm.grow(400)?;
    let q = prm.query(start, goal)?;
    let found = dijkstra(&q, q.start(), q.goal())?;
    let path = found.path.as_ref().ok_or("no PRM path")?;
    println!(
        "prm*: {} nodes, {} edges, {} components, cost {:.3}",
        prm.node_count(),
        prm.edge_count(),
        prm.component_count(),
        found.cost().unwrap_or(f64::NAN)
    );
    let svg = WorldSvg::new(&world)
        .edges(prm.edge_ends())
        .nodes((0..prm.node_count() as u32).map(|u| prm.position(u)))
        .path(&q.positions(&path.nodes))
        .start(start)
        .goal(goal)
        .title("PRM*: 400 Halton samples, k = e(1 + 1/d) ln n nearest, exact segment checks")
        .to_svg();
    write("graph-prm.svg", svg)?;

    let space = Dubins::new(world.bounds(), 1.0)?;
    let options = PrmOptions {
        sampler: PrmSampler::Halton,
        connection: Connection::Nearest { k: 15 },
        ..PrmOptions::default()
    };
    let mut dubins = PolygonPrm::with_space(world.clone(), space, options)?;
    dubins.grow(1500)?;
    let (a, b) = (
        Pose::new(start.coords, std::f64::consts::FRAC_PI_4),
        Pose::new(goal.coords, std::f64::consts::FRAC_PI_4),
    );
    let q = dubins.query(a, b)?;
    let found = dijkstra(&q, q.start(), q.goal())?;
    let path = found.path.as_ref().ok_or("no Dubins path")?;
    println!(
        "dubins prm: {} nodes, {} edges, cost {:.3}",
        dubins.node_count(),
        dubins.edge_count(),
        found.cost().unwrap_or(f64::NAN)
    );
    let mut curve = Vec::new();
    for pair in path.nodes.windows(2) {
        let piece = DubinsPath::shortest(&q.position(pair[0]), &q.position(pair[1]), 1.0)?;
        curve.extend(piece.sample(0.1)?.iter().map(|p| Point::from(p.translation.vector)));
    }
    let svg = WorldSvg::new(&world)
        .poses((0..dubins.node_count() as u32).map(|u| dubins.position(u)))
        .path(&curve)
        .start(start)
        .goal(goal)
        .title("Dubins roadmap: 1500 Halton poses, directed Dubins edges (turning radius 1)")
        .to_svg();
    Ok(write("graph-dubins-prm.svg", svg)?)
}

/// The six Dubins words between two poses a few turning radii apart, the shortest drawn bold.
/// A pose in a figure: a dot at pixel `(x, y)`, a stroke along `heading`, and its name.
fn pose_marker((x, y): (f64, f64), heading: f64, name: &str) -> String {
    let (tx, ty) = (x + 24.0 * heading.cos(), y - 24.0 * heading.sin());
    format!(
        "<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"5\"/><line x1=\"{x:.1}\" y1=\"{y:.1}\" x2=\"{tx:.1}\" y2=\"{ty:.1}\" stroke=\"black\" stroke-width=\"2.5\"/><text x=\"{:.1}\" y=\"{:.1}\">{name}</text>\n",
        x + 8.0,
        y + 18.0
    )
}

/// Parallel parking: the shortest Reeds-Shepp path (forward pieces solid, reverse pieces dashed,
/// cusps in red) beside the shortest Dubins path (grey) between the same poses.
fn reeds_shepp_parking() -> Result<String, Box<dyn std::error::Error>> {
    use std::fmt::Write;
    use trailmark::core::dubins::DubinsPath;
    use trailmark::core::geometry::{Pose, Vector};
    use trailmark::core::reeds_shepp::{Gear, ReedsSheppPath};

    let start = Pose::new(Vector::new(0.0, 0.0), 0.0);
    let goal = Pose::new(Vector::new(0.6, 1.2), 0.0);
    let path = ReedsSheppPath::shortest(&start, &goal, 1.0)?;
    let dubins = DubinsPath::shortest(&start, &goal, 1.0)?;
    // World window [-1.2, 3] x [-0.8, 3.3], 100 pixels a unit, y up.
    let (scale, x0, y1) = (100.0, -1.2, 3.3);
    let px = |x: f64, y: f64| ((x - x0) * scale, (y1 - y) * scale);
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0}\" height=\"{:.0}\" font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
        4.2 * scale + 250.0,
        4.1 * scale
    );
    let polyline = |poses: &[Pose]| -> String {
        poses
            .iter()
            .map(|p| {
                let (x, y) = px(p.translation.vector.x, p.translation.vector.y);
                format!("{x:.1},{y:.1}")
            })
            .collect::<Vec<_>>()
            .join(" ")
    };
    writeln!(
        svg,
        "<polyline fill=\"none\" stroke=\"#999\" stroke-width=\"1.6\" points=\"{}\"/>",
        polyline(&dubins.sample(0.02)?)
    )?;
    // Each piece on its own, solid forward and dashed in reverse.
    let mut driven = 0.0;
    for segment in path.segments() {
        let steps = (segment.length / 0.02).ceil().max(1.0) as usize;
        let poses: Vec<Pose> = (0..=steps)
            .map(|k| path.pose_at((driven + segment.length * k as f64 / steps as f64).min(path.length())))
            .collect::<Result<_, _>>()?;
        let dash = if segment.gear == Gear::Reverse { " stroke-dasharray=\"8 5\"" } else { "" };
        writeln!(
            svg,
            "<polyline fill=\"none\" stroke=\"#1b6ac9\" stroke-width=\"3.5\"{dash} points=\"{}\"/>",
            polyline(&poses)
        )?;
        driven += segment.length;
    }
    for s in path.cusps() {
        let p = path.pose_at(s)?;
        let (x, y) = px(p.translation.vector.x, p.translation.vector.y);
        writeln!(svg, "<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"6\" fill=\"#d7301f\"/>")?;
    }
    for (pose, name) in [(&start, "start"), (&goal, "goal")] {
        svg.push_str(&pose_marker(
            px(pose.translation.vector.x, pose.translation.vector.y),
            pose.rotation.angle(),
            name,
        ));
    }
    let legend = [
        ("#1b6ac9", format!("Reeds-Shepp {path}, {:.3}", path.length())),
        ("#d7301f", format!("{} cusp(s): the car changes gear", path.cusps().len())),
        ("#999", format!("Dubins {}, {:.3}", dubins.word(), dubins.length())),
    ];
    for (i, (colour, text)) in legend.iter().enumerate() {
        writeln!(
            svg,
            "<text x=\"{:.0}\" y=\"{:.0}\" fill=\"{colour}\">{text}</text>",
            4.2 * scale + 10.0,
            24.0 + 20.0 * i as f64
        )?;
    }
    println!("reeds-shepp {path}: length {:.3}, dubins {:.3}", path.length(), dubins.length());
    svg.push_str("</svg>\n");
    Ok(svg)
}

fn dubins_words() -> Result<String, Box<dyn std::error::Error>> {
    use std::fmt::Write;
    use trailmark::core::dubins::{DubinsPath, DubinsWord};
    use trailmark::core::geometry::{Pose, Vector};

    let start = Pose::new(Vector::new(0.0, 0.0), std::f64::consts::FRAC_PI_2);
    let goal = Pose::new(Vector::new(2.2, 0.6), -2.4);
    let best = DubinsPath::shortest(&start, &goal, 1.0)?;
    // World window [-2.6, 5] x [-2.6, 3.2], 60 pixels a unit, y up.
    let (scale, x0, y1) = (60.0, -2.6, 3.2);
    let px = |x: f64, y: f64| ((x - x0) * scale, (y1 - y) * scale);
    let colours = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#a6761d"];
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0}\" height=\"{:.0}\" font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
        7.6 * scale + 190.0,
        5.8 * scale
    );
    for (i, word) in DubinsWord::ALL.into_iter().enumerate() {
        let label = match DubinsPath::with_word(&start, &goal, 1.0, word) {
            Ok(path) => {
                let points: Vec<String> = path
                    .sample(0.02)?
                    .iter()
                    .map(|p| {
                        let (x, y) = px(p.translation.vector.x, p.translation.vector.y);
                        format!("{x:.1},{y:.1}")
                    })
                    .collect();
                let width = if word == best.word() { 4.0 } else { 1.6 };
                writeln!(
                    svg,
                    "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{width}\" points=\"{}\"/>",
                    colours[i],
                    points.join(" ")
                )?;
                println!("dubins {word}: length {:.3}", path.length());
                format!("{word} {:.3}{}", path.length(), if word == best.word() { " (shortest)" } else { "" })
            }
            Err(_) => format!("{word}: none"),
        };
        writeln!(
            svg,
            "<text x=\"{:.0}\" y=\"{:.0}\" fill=\"{}\">{label}</text>",
            7.6 * scale + 10.0,
            24.0 + 20.0 * i as f64,
            colours[i]
        )?;
    }
    for (pose, name) in [(&start, "start"), (&goal, "goal")] {
        svg.push_str(&pose_marker(
            px(pose.translation.vector.x, pose.translation.vector.y),
            pose.rotation.angle(),
            name,
        ));
    }
    svg.push_str("</svg>\n");
    Ok(svg)
}
