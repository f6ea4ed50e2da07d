//! The OMPL peer of `cargo xtask bench --with-ompl`: builds `benches/ompl/driver.cpp` against
//! the system's OMPL (found with pkg-config) and trailmark's exact checker
//! (`benches/ompl/checker`, a static library), then runs OMPL's planners on the harness's own
//! worlds and queries.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde::{Deserialize, Serialize};
use trailmark::core::world::PolygonWorld;
use trailmark::sample::benchmark::RunRecord;

/// How to get what the driver needs, for the message shown when it is missing.
pub const INSTALL: &str = "install OMPL and nlohmann-json with `sudo apt-get install libompl-dev \
                           nlohmann-json3-dev` (Debian, Ubuntu) and run again";

/// The compiled driver.
pub struct OmplDriver {
    program: PathBuf,
    /// The OMPL version pkg-config reports.
    pub version: String,
}

/// What the driver is asked to run.
#[derive(Serialize)]
pub struct OmplInput<'a> {
    /// A polygon world (the same document trailmark reads).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub world: Option<&'a PolygonWorld>,
    /// Or a box world.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub boxes: Option<OmplBoxes>,
    /// For a car in the polygon world: `reeds_shepp` or `dubins` (queries and paths of poses).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub space: Option<&'static str>,
    /// The car's turning radius.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub turning_radius: Option<f64>,
    /// `rrt`, `rrt_connect`, `rrt_star` or `prm_star`; in a box world also `informed_rrt_star`
    /// and `bit_star`.
    pub planner: &'a str,
    /// The start's coordinates, then the goal's, per query.
    pub queries: Vec<Vec<f64>>,
    /// Runs per query.
    pub runs: usize,
    /// OMPL's global seed.
    pub seed: u64,
    /// The iteration limit (0: none).
    pub max_iterations: u64,
    /// The time limit per run, seconds (for `prm_star`: of growing the roadmap).
    pub time_limit_s: f64,
    /// For `prm_star`: the milestones of the roadmap the queries share (0 for the others).
    pub roadmap_size: usize,
}

/// A box world for the driver: the region and the boxes' corners.
#[derive(Serialize)]
pub struct OmplBoxes {
    /// The region's low corner.
    pub low: Vec<f64>,
    /// Its high corner.
    pub high: Vec<f64>,
    /// `[low corner, high corner]` per box.
    pub obstacles: Vec<[Vec<f64>; 2]>,
}

/// How OMPL's PRMstar grew the roadmap its queries share.
#[derive(Debug, Clone, Deserialize, Serialize)]
pub struct OmplRoadmap {
    /// The time of growing it, seconds.
    pub time_s: f64,
    /// Its milestones.
    pub milestones: u64,
    /// Its edges.
    pub edges: u64,
    /// State and motion checks while growing it.
    pub collision_checks: u64,
}

/// One run of an OMPL planner.
#[derive(Debug, Clone, Deserialize, Serialize)]
pub struct OmplRun {
    /// The index of the query.
    pub query: usize,
    /// The run of that query.
    pub run: usize,
    /// `exact`, `approximate` or `none`.
    pub status: String,
    /// The time of `Planner::solve`, seconds.
    pub time_s: f64,
    /// The times the termination condition was asked (once per iteration).
    pub iterations: u64,
    /// State and motion checks.
    pub collision_checks: u64,
    /// The vertices of the planner's data (tree or graph states).
    pub states: u64,
    /// The path length (`None` without a path).
    pub cost: Option<f64>,
    /// The path's states.
    pub path: Vec<Vec<f64>>,
    /// `(seconds, cost)` at every improvement the planner reported.
    pub improvements: Vec<(f64, f64)>,
}

impl OmplRun {
    /// Whether OMPL found an exact solution.
    pub fn exact(&self) -> bool {
        self.status == "exact"
    }

    /// The run as a record of the OMPL-format log.
    pub fn record(&self) -> RunRecord {
        RunRecord {
            time_s: self.time_s,
            solved: self.exact(),
            approximate: self.status == "approximate",
            memory_bytes: None,
            graph_states: self.states,
            solution_length: self.cost.filter(|_| self.exact()),
            iterations: self.iterations,
            collision_checks: self.collision_checks,
            progress: self.improvements.clone(),
            ..RunRecord::default()
        }
    }
}

#[derive(Deserialize)]
struct OmplOutput {
    runs: Vec<OmplRun>,
    #[serde(default)]
    build: Option<OmplRoadmap>,
}

/// The standard output of `command`, trimmed; an error with its standard error when it fails.
pub(super) fn run_tool(command: &mut Command, what: &str) -> Result<String, String> {
    let out = command.output().map_err(|e| format!("cannot run {what}: {e}"))?;
    if !out.status.success() {
        return Err(format!("{what} failed:\n{}", String::from_utf8_lossy(&out.stderr)));
    }
    Ok(String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// What `pkg-config` answers to `args`.
pub(super) fn pkg_config(args: &[&str]) -> Result<String, String> {
    run_tool(Command::new("pkg-config").args(args), &format!("pkg-config {}", args.join(" ")))
}

/// Whether file `a` is newer than `b` (or either's time is unknown).
pub(super) fn newer(a: &Path, b: &Path) -> bool {
    let time = |p: &Path| std::fs::metadata(p).and_then(|m| m.modified()).ok();
    match (time(a), time(b)) {
        (Some(a), Some(b)) => a > b,
        _ => true,
    }
}

/// Compiles the C++17 driver `source` into `program` (its folder made) against the pkg-config
/// `packages` and the libraries of `libraries` (only their `-l` part: Debian's ompl.pc names
/// Boost files its runtime does not need, and fcl.pc a library folder CMake did not fill in),
/// `objects` linked in too.
pub(super) fn compile(
    source: &Path,
    program: &Path,
    packages: &[&str],
    libraries: &[&str],
    objects: &[&Path],
) -> Result<(), String> {
    if let Some(folder) = program.parent() {
        std::fs::create_dir_all(folder).map_err(|e| e.to_string())?;
    }
    let cflags = pkg_config(&[&["--cflags"], packages].concat())?;
    let libs = pkg_config(&[&["--libs-only-l"], libraries].concat())?;
    let compiler = std::env::var("CXX").unwrap_or_else(|_| "c++".into());
    // Written aside, then renamed into place: two builds at once (tests run in parallel) never
    // leave a half-written program for the other to run.
    static BUILDS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let build = BUILDS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let aside = program.with_extension(format!("{}-{build}.part", std::process::id()));
    let mut command = Command::new(&compiler);
    command
        .args(["-O2", "-DNDEBUG"])
        .args(cflags.split_whitespace())
        .arg("-std=c++17")
        .arg(source)
        .arg("-o")
        .arg(&aside)
        .args(objects)
        .args(libs.split_whitespace())
        .args(["-ldl", "-lm"]);
    let built = run_tool(&mut command, &format!("the C++ compiler ({compiler})")).map(|_| ());
    let placed = built.and_then(|()| std::fs::rename(&aside, program).map_err(|e| e.to_string()));
    if placed.is_err() {
        let _ = std::fs::remove_file(&aside);
    }
    placed
}

impl OmplDriver {
    /// Builds the driver (when its source or the checker changed); an error that says what to
    /// install when OMPL or nlohmann-json is missing.
    pub fn build() -> Result<OmplDriver, String> {
        let version =
            pkg_config(&["--modversion", "ompl"]).map_err(|_| format!("OMPL not found: {INSTALL}"))?;
        pkg_config(&["--exists", "nlohmann_json"])
            .map_err(|_| format!("nlohmann-json not found: {INSTALL}"))?;
        let root = crate::workspace::root();
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        run_tool(
            Command::new(cargo).current_dir(&root).args([
                "build",
                "--quiet",
                "--release",
                "--package",
                "trailmark-ompl-checker",
            ]),
            "cargo build of the checker library",
        )?;
        let library = root.join("target/release/libtrailmark_ompl_checker.a");
        let source = root.join("benches/ompl/driver.cpp");
        let folder = root.join("target/ompl");
        let program = folder.join("ompl-driver");
        if newer(&source, &program) || newer(&library, &program) {
            errln!("compiling the OMPL driver (OMPL {version})...");
            compile(&source, &program, &["ompl", "nlohmann_json"], &["ompl"], &[&library])?;
        }
        Ok(OmplDriver { program, version })
    }

    /// Runs `input` and returns the runs, query by query.
    pub fn run(&self, input: &OmplInput<'_>) -> Result<Vec<OmplRun>, String> {
        Ok(self.output(input)?.runs)
    }

    /// Runs `input` of `prm_star`: the roadmap's build, then the runs, query by query.
    pub fn run_roadmap(&self, input: &OmplInput<'_>) -> Result<(OmplRoadmap, Vec<OmplRun>), String> {
        let out = self.output(input)?;
        let build = out.build.ok_or("the OMPL driver did not report a roadmap")?;
        Ok((build, out.runs))
    }

    /// OMPL's GNAT given the first `base` of `points` (`dimension` numbers each), then asked
    /// for each further one's nearest before storing it: the fastest of `runs` runs, seconds,
    /// and the sum of the answers (indices).
    pub fn nearest(
        &self,
        dimension: usize,
        points: &[f64],
        base: usize,
        runs: usize,
    ) -> Result<(f64, u64), String> {
        #[derive(Deserialize)]
        struct Answer {
            time_s: f64,
            checksum: u64,
        }
        #[derive(Deserialize)]
        struct Output {
            nearest: Answer,
        }
        let input = serde_json::json!({"nearest": {"dimension": dimension, "points": points, "base": base, "runs": runs}});
        let out: Output = serde_json::from_str(&self.call(&input.to_string())?)
            .map_err(|e| format!("the OMPL driver's output: {e}"))?;
        Ok((out.nearest.time_s, out.nearest.checksum))
    }

    /// Runs the driver on the input `text`; its output.
    fn call(&self, text: &str) -> Result<String, String> {
        let file = self.program.with_file_name(format!("input-{}.json", std::process::id()));
        std::fs::write(&file, text).map_err(|e| format!("cannot write {}: {e}", file.display()))?;
        let out = run_tool(Command::new(&self.program).arg(&file), "the OMPL driver");
        let _ = std::fs::remove_file(&file);
        out
    }

    fn output(&self, input: &OmplInput<'_>) -> Result<OmplOutput, String> {
        let text = serde_json::to_string(input).map_err(|e| e.to_string())?;
        serde_json::from_str(&self.call(&text)?).map_err(|e| format!("the OMPL driver's output: {e}"))
    }
}
