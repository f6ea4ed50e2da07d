// The OMPL peer of `cargo xtask bench --with-ompl`: runs OMPL's RRT, RRTConnect, RRTstar and
// PRMstar on the harness's polygon worlds and prints every run as JSON, for the harness to set
// beside trailmark's own runs on the same queries.
//
// States and motions are validated by trailmark's exact checker through its C interface
// (benches/ompl/checker), so both libraries answer the same collision questions at the same
// cost per question; what differs is the planner. xtask compiles this file with
// `g++ $(pkg-config --cflags --libs ompl)` and links the checker's static library.
//
// Usage: ompl-driver INPUT.json > RUNS.json, where INPUT.json is
//   {"world": {"bounds": [...], "obstacles": [...], "robot_radius": r},
//    "planner": "rrt" | "rrt_connect" | "rrt_star" | "prm_star",
//    "queries": [[ax, ay, bx, by], ...], "runs": 1, "seed": 1,
//    "max_iterations": 10000 (0: no limit), "time_limit_s": 10.0, "roadmap_size": 2000}
// and every run prints as {"query", "run", "status": "exact" | "approximate" | "none",
// "time_s", "iterations", "collision_checks", "states", "cost", "path", "improvements"}.
//
// A car instead: "space": "reeds_shepp" | "dubins" and "turning_radius": r beside a polygon
// world, queries of 6 numbers (start pose [x, y, heading], then goal pose), paths of poses. The
// planners (rrt_connect, rrt_star) run in OMPL's ReedsSheppStateSpace or DubinsStateSpace; a
// state is checked by the point test and a motion by trailmark's exact test of the shortest
// curve between its ends (tm_reeds_shepp_is_free, tm_dubins_is_free), as trailmark's car spaces
// check them.
//
// A box world instead: {"boxes": {"low": [...], "high": [...], "obstacles": [[[lo...], [hi...]],
// ...]}} in place of "world", queries of 2n numbers (start, then goal), paths of n-vectors.
// States and motions are then checked by the same tests trailmark's BoxWorld makes, written here
// in C++: a state inside no box's open interior, a segment entering none (the slab test). The
// planners: rrt_connect, rrt_star, informed_rrt_star, bit_star and prm_star (through solve(),
// each run its own roadmap, under the time limit; or, given a roadmap_size, multi-query as below).
//
// Nearest neighbours alone instead: {"nearest": {"dimension": n, "points": [x0, y0, x1, ...],
// "base": b, "runs": r}}. OMPL's default structure for a tree planner in a metric space
// (NearestNeighborsGNATNoThreadSafety, default settings) is given the first `base` points,
// then each further point is asked for its nearest and added, as a connect phase does; prints
// {"nearest": {"time_s": the fastest run's time of that loop, "checksum": sum of the answers}}.
//
// `prm_star` is multi-query: one roadmap of `roadmap_size` milestones is grown first (printed as
// "build": {"time_s", "milestones", "edges", "collision_checks"}), then each query joins its
// start and goal to it as PRM::solve does (addMilestone, which keeps them in the roadmap) and
// searches it with PRM's own A* (constructSolution) when they share a component. solve() itself
// is not called: it polls for a solution from a second thread every millisecond, which would
// time the polling, not the planner.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/datastructures/NearestNeighborsGNATNoThreadSafety.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/config.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

extern "C" {
struct TmChecker;
TmChecker *tm_checker_new(const char *json);
void tm_checker_free(TmChecker *checker);
bool tm_point_is_free(const TmChecker *checker, double x, double y);
bool tm_segment_is_free(const TmChecker *checker, double ax, double ay, double bx, double by);
bool tm_reeds_shepp_is_free(const TmChecker *checker, const double *a, const double *b, double r);
bool tm_dubins_is_free(const TmChecker *checker, const double *a, const double *b, double r);
}

namespace ob = ompl::base;
namespace og = ompl::geometric;
using json = nlohmann::json;

namespace {

// Collision questions asked during the current run.
std::atomic<unsigned long> g_checks{0};

const double *xy(const ob::State *s) { return s->as<ob::RealVectorStateSpace::StateType>()->values; }

// Axis-aligned boxes, tested as trailmark's BoxWorld tests them.
struct Boxes {
    unsigned n = 0;
    std::vector<std::vector<double>> lo, hi;

    bool state_free(const double *q) const {
        for (size_t b = 0; b < lo.size(); ++b) {
            bool inside = true;
            for (unsigned i = 0; i < n && inside; ++i) {
                inside = q[i] > lo[b][i] && q[i] < hi[b][i];
            }
            if (inside) {
                return false;
            }
        }
        return true;
    }

    // Whether the segment a-b meets box b's open interior: a non-empty open interval of t in
    // [0, 1] strictly inside on every axis.
    bool enters(const double *a, const double *c, size_t b) const {
        double t0 = 0.0, t1 = 1.0;
        for (unsigned i = 0; i < n; ++i) {
            double d = c[i] - a[i];
            if (d == 0.0) {
                if (!(a[i] > lo[b][i] && a[i] < hi[b][i])) {
                    return false;
                }
                continue;
            }
            double u = (lo[b][i] - a[i]) / d, v = (hi[b][i] - a[i]) / d;
            t0 = std::max(t0, std::min(u, v));
            t1 = std::min(t1, std::max(u, v));
            if (t0 >= t1) {
                return false;
            }
        }
        return t0 < t1;
    }

    bool segment_free(const double *a, const double *c) const {
        for (size_t b = 0; b < lo.size(); ++b) {
            if (enters(a, c, b)) {
                return false;
            }
        }
        return true;
    }
};



// A state test and an exact motion test, the same questions trailmark's planners ask (no
// fixed-resolution sampling of motions).
using StateTest = std::function<bool(const ob::State *)>;
using MotionTest = std::function<bool(const ob::State *, const ob::State *)>;

class StateChecker : public ob::StateValidityChecker {
  public:
    StateChecker(const ob::SpaceInformationPtr &si, StateTest test) : ob::StateValidityChecker(si), test_(std::move(test)) {}
    bool isValid(const ob::State *s) const override {
        ++g_checks;
        return test_(s);
    }

  private:
    StateTest test_;
};

class MotionChecker : public ob::MotionValidator {
  public:
    MotionChecker(const ob::SpaceInformationPtr &si, MotionTest test) : ob::MotionValidator(si), test_(std::move(test)) {}
    bool checkMotion(const ob::State *s1, const ob::State *s2) const override {
        ++g_checks;
        bool ok = test_(s1, s2);
        if (ok) {
            ++valid_;
        } else {
            ++invalid_;
        }
        return ok;
    }
    // Planners of this driver never ask for the last valid state; answer conservatively.
    bool checkMotion(const ob::State *s1, const ob::State *s2, std::pair<ob::State *, double> &last) const override {
        if (checkMotion(s1, s2)) {
            return true;
        }
        if (last.first != nullptr) {
            si_->copyState(last.first, s1);
        }
        last.second = 0.0;
        return false;
    }

  private:
    MotionTest test_;
};

// A car's pose: x, y and heading.
void pose_of(const ob::State *s, double *q) {
    const auto *p = s->as<ob::SE2StateSpace::StateType>();
    q[0] = p->getX();
    q[1] = p->getY();
    q[2] = p->getYaw();
}

// PRMstar with its query steps public: what PRM::solve does for one start and one goal, without
// the polling thread.
class QueryPrm : public og::PRMstar {
  public:
    using og::PRMstar::PRMstar;

    // The path from `a` to `b` through the roadmap, or null when they are not connected.
    ob::PathPtr query(const ob::State *a, const ob::State *b) {
        Vertex start = addMilestone(si_->cloneState(a));
        Vertex goal = addMilestone(si_->cloneState(b));
        if (!sameComponent(start, goal)) {
            return nullptr;
        }
        return constructSolution(start, goal);
    }
};

ob::PlannerPtr make_planner(const std::string &name, const ob::SpaceInformationPtr &si) {
    if (name == "rrt") {
        return std::make_shared<og::RRT>(si);
    }
    if (name == "rrt_connect") {
        return std::make_shared<og::RRTConnect>(si);
    }
    if (name == "rrt_star") {
        return std::make_shared<og::RRTstar>(si);
    }
    if (name == "informed_rrt_star") {
        return std::make_shared<og::InformedRRTstar>(si);
    }
    if (name == "bit_star") {
        return std::make_shared<og::BITstar>(si);
    }
    if (name == "prm_star") {
        return std::make_shared<og::PRMstar>(si);
    }
    return nullptr;
}

std::string version() {
    return std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) + "." +
           std::to_string(OMPL_PATCH_VERSION);
}

// Prints the document: the runs, and the roadmap's build when there is one.
void print(const json &runs, const json *build) {
    json doc;
    doc["ompl_version"] = version();
    doc["runs"] = runs;
    if (build != nullptr) {
        doc["build"] = *build;
    }
    std::cout << doc.dump() << "\n";
}

json path_of(og::PathGeometric &path, const ob::StateSpacePtr &space) {
    json points = json::array();
    for (const ob::State *s : path.getStates()) {
        std::vector<double> q;
        for (unsigned i = 0; i < space->getDimension(); ++i) {
            q.push_back(*space->getValueAddressAtIndex(s, i));
        }
        points.push_back(q);
    }
    return points;
}

// PRMstar, multi-query: one roadmap, then every query on it.
int run_prm(const json &input, const ob::SpaceInformationPtr &si, const ob::StateSpacePtr &space) {
    const unsigned n = space->getDimension();
    unsigned long size = input.value("roadmap_size", 0UL);
    double time_limit = input.value("time_limit_s", 10.0);
    const auto &queries = input.at("queries");
    auto prm = std::make_shared<QueryPrm>(si);
    // PRM's setup needs a problem definition (for its cost objective); its start and goal
    // are not used.
    auto pdef = std::make_shared<ob::ProblemDefinition>(si);
    ob::ScopedState<> anywhere(space);
    space->allocDefaultStateSampler()->sampleUniform(anywhere.get());
    pdef->setStartAndGoalStates(anywhere, anywhere);
    pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
    prm->setProblemDefinition(pdef);
    prm->setup();
    g_checks = 0;
    auto clock = std::chrono::steady_clock::now();
    auto seconds = [&clock] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count(); };
    prm->growRoadmap(ob::plannerOrTerminationCondition(
        ob::PlannerTerminationCondition([&prm, size] { return prm->milestoneCount() >= size; }),
        ob::timedPlannerTerminationCondition(time_limit)));
    json build;
    build["time_s"] = seconds();
    build["milestones"] = prm->milestoneCount();
    build["edges"] = prm->edgeCount();
    build["collision_checks"] = g_checks.load();
    json out = json::array();
    ob::ScopedState<> start(space), goal(space);
    for (size_t q = 0; q < queries.size(); ++q) {
        std::vector<double> ends = queries[q].get<std::vector<double>>();
        for (unsigned i = 0; i < n; ++i) {
            start[i] = ends[i];
            goal[i] = ends[n + i];
        }
        g_checks = 0;
        clock = std::chrono::steady_clock::now();
        ob::PathPtr path = prm->query(start.get(), goal.get());
        json row;
        row["time_s"] = seconds();
        row["query"] = q;
        row["run"] = 0;
        row["iterations"] = 0;
        row["collision_checks"] = g_checks.load();
        row["states"] = prm->milestoneCount();
        row["status"] = path ? "exact" : "none";
        row["improvements"] = json::array();
        if (path) {
            auto *geometric = path->as<og::PathGeometric>();
            row["cost"] = geometric->length();
            row["path"] = path_of(*geometric, space);
        } else {
            row["cost"] = nullptr;
            row["path"] = json::array();
        }
        out.push_back(row);
    }
    print(out, &build);
    return 0;
}

}  // namespace

// The connect-phase loop of the header's "nearest" input on OMPL's GNAT.
static int run_nearest(const json &spec) {
    std::size_t n = 0, base = 0;
    std::vector<double> points;
    int runs = 3;
    try {
        n = spec.at("dimension").get<std::size_t>();
        points = spec.at("points").get<std::vector<double>>();
        base = spec.at("base").get<std::size_t>();
        runs = spec.value("runs", 3);
    } catch (const std::exception &e) {
        std::cerr << "bad nearest input: " << e.what() << "\n";
        return 2;
    }
    // At least one point stored before the first question (GNAT's nearest needs one).
    if (n == 0 || points.size() % n != 0 || base == 0 || base > points.size() / n || runs < 1) {
        std::cerr << "bad nearest input\n";
        return 2;
    }
    const std::size_t count = points.size() / n;
    double best = 1e300;
    unsigned long long checksum = 0;
    for (int run = 0; run < runs; ++run) {
        ompl::NearestNeighborsGNATNoThreadSafety<std::size_t> gnat;
        gnat.setDistanceFunction([&points, n](const std::size_t &a, const std::size_t &b) {
            double sum = 0.0;
            for (std::size_t k = 0; k < n; ++k) {
                double d = points[a * n + k] - points[b * n + k];
                sum += d * d;
            }
            return std::sqrt(sum);
        });
        for (std::size_t i = 0; i < base; ++i) {
            gnat.add(i);
        }
        checksum = 0;
        auto start = std::chrono::steady_clock::now();
        for (std::size_t i = base; i < count; ++i) {
            checksum += gnat.nearest(i);
            gnat.add(i);
        }
        std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
        best = std::min(best, took.count());
    }
    json out;
    out["nearest"] = {{"time_s", best}, {"checksum", checksum}};
    std::cout << out.dump() << "\n";
    return 0;
}

int main(int argc, char **argv) {
    if (argc != 2) {
        std::cerr << "usage: " << argv[0] << " INPUT.json\n";
        return 2;
    }
    std::ifstream file(argv[1]);
    if (!file) {
        std::cerr << "cannot read " << argv[1] << "\n";
        return 2;
    }
    json input;
    try {
        input = json::parse(file);
    } catch (const std::exception &e) {
        std::cerr << "bad input: " << e.what() << "\n";
        return 2;
    }
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::RNG::setSeed(input.value("seed", 1UL));
    if (input.contains("nearest")) {
        return run_nearest(input.at("nearest"));
    }

    TmChecker *checker = nullptr;
    Boxes boxes;
    std::shared_ptr<ob::RealVectorStateSpace> region;
    ob::StateSpacePtr space;
    std::string car = input.value("space", std::string());
    if (input.contains("boxes")) {
        const auto &w = input.at("boxes");
        std::vector<double> low = w.at("low").get<std::vector<double>>();
        std::vector<double> high = w.at("high").get<std::vector<double>>();
        boxes.n = low.size();
        for (const auto &o : w.at("obstacles")) {
            boxes.lo.push_back(o.at(0).get<std::vector<double>>());
            boxes.hi.push_back(o.at(1).get<std::vector<double>>());
        }
        region = std::make_shared<ob::RealVectorStateSpace>(boxes.n);
        ob::RealVectorBounds b(boxes.n);
        for (unsigned i = 0; i < boxes.n; ++i) {
            b.setLow(i, low[i]);
            b.setHigh(i, high[i]);
        }
        region->setBounds(b);
        space = region;
    } else {
        std::string world_text = input.at("world").dump();
        checker = tm_checker_new(world_text.c_str());
        if (checker == nullptr) {
            std::cerr << "bad world\n";
            return 2;
        }
        std::vector<double> bounds = input.at("world").at("bounds").get<std::vector<double>>();
        ob::RealVectorBounds b(2);
        b.setLow(0, bounds[0]);
        b.setLow(1, bounds[1]);
        b.setHigh(0, bounds[2]);
        b.setHigh(1, bounds[3]);
        double radius = input.value("turning_radius", 1.0);
        if (car == "reeds_shepp" || car == "dubins") {
            auto se2 = car == "reeds_shepp" ? ob::StateSpacePtr(std::make_shared<ob::ReedsSheppStateSpace>(radius))
                                            : ob::StateSpacePtr(std::make_shared<ob::DubinsStateSpace>(radius));
            se2->as<ob::SE2StateSpace>()->setBounds(b);
            space = se2;
        } else if (!car.empty()) {
            std::cerr << "unknown space " << car << "\n";
            return 2;
        } else {
            region = std::make_shared<ob::RealVectorStateSpace>(2);
            region->setBounds(b);
            space = region;
        }
    }
    const unsigned n = space->getDimension();
    auto si = std::make_shared<ob::SpaceInformation>(space);
    if (!car.empty()) {
        // A car's state: its reference point by the point test; its motion: the shortest curve
        // between its ends, checked exactly.
        si->setStateValidityChecker(std::make_shared<StateChecker>(si, [checker](const ob::State *s) {
            double q[3];
            pose_of(s, q);
            return tm_point_is_free(checker, q[0], q[1]);
        }));
        bool reverse = car == "reeds_shepp";
        double radius = input.value("turning_radius", 1.0);
        si->setMotionValidator(std::make_shared<MotionChecker>(si, [checker, reverse, radius](const ob::State *s1, const ob::State *s2) {
            double a[3], b[3];
            pose_of(s1, a);
            pose_of(s2, b);
            return reverse ? tm_reeds_shepp_is_free(checker, a, b, radius) : tm_dubins_is_free(checker, a, b, radius);
        }));
    } else if (checker != nullptr) {
        si->setStateValidityChecker(std::make_shared<StateChecker>(
            si, [checker](const ob::State *s) { return tm_point_is_free(checker, xy(s)[0], xy(s)[1]); }));
        si->setMotionValidator(std::make_shared<MotionChecker>(si, [checker](const ob::State *s1, const ob::State *s2) {
            const double *a = xy(s1), *b = xy(s2);
            return tm_segment_is_free(checker, a[0], a[1], b[0], b[1]);
        }));
    } else {
        // In the region (trailmark's planners refuse what is not), outside every box.
        auto in_region = [region](const double *q) {
            const auto &b = region->getBounds();
            for (size_t i = 0; i < b.low.size(); ++i) {
                if (!(q[i] >= b.low[i] && q[i] <= b.high[i])) {
                    return false;
                }
            }
            return true;
        };
        si->setStateValidityChecker(std::make_shared<StateChecker>(si, [&boxes, in_region](const ob::State *s) {
            return in_region(xy(s)) && boxes.state_free(xy(s));
        }));
        si->setMotionValidator(std::make_shared<MotionChecker>(si, [&boxes, in_region](const ob::State *s1, const ob::State *s2) {
            const double *a = xy(s1), *b = xy(s2);
            return in_region(a) && in_region(b) && boxes.segment_free(a, b);
        }));
    }
    si->setup();

    std::string name = input.at("planner").get<std::string>();
    // A polygon world's PRMstar always builds one roadmap for its queries; a box world's does
    // when it is given a roadmap size (otherwise each run is its own solve()).
    if (name == "prm_star" && (checker != nullptr || input.value("roadmap_size", 0UL) > 0)) {
        int code = run_prm(input, si, space);
        tm_checker_free(checker);
        return code;
    }
    unsigned int max_iterations = input.value("max_iterations", 0U);
    double time_limit = input.value("time_limit_s", 10.0);
    int runs = input.value("runs", 1);
    json out = json::array();
    const auto &queries = input.at("queries");
    for (size_t q = 0; q < queries.size(); ++q) {
        std::vector<double> ends = queries[q].get<std::vector<double>>();
        for (int run = 0; run < runs; ++run) {
            ob::PlannerPtr planner = make_planner(name, si);
            if (!planner) {
                std::cerr << "unknown planner " << name << "\n";
                return 2;
            }
            auto pdef = std::make_shared<ob::ProblemDefinition>(si);
            ob::ScopedState<> start(space), goal(space);
            for (unsigned i = 0; i < n; ++i) {
                start[i] = ends[i];
                goal[i] = ends[n + i];
            }
            pdef->setStartAndGoalStates(start, goal);
            pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
            json improvements = json::array();
            auto clock = std::chrono::steady_clock::now();
            auto seconds = [&clock] {
                return std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
            };
            pdef->setIntermediateSolutionCallback(
                [&](const ob::Planner *, const std::vector<const ob::State *> &, const ob::Cost cost) {
                    improvements.push_back({seconds(), cost.value()});
                });
            planner->setProblemDefinition(pdef);
            planner->setup();
            // The iteration limit: the termination condition is asked once per iteration.
            ob::IterationTerminationCondition iterations(max_iterations > 0 ? max_iterations : ~0U);
            ob::PlannerTerminationCondition ptc = ob::plannerOrTerminationCondition(
                ob::PlannerTerminationCondition(iterations), ob::timedPlannerTerminationCondition(time_limit));
            g_checks = 0;
            clock = std::chrono::steady_clock::now();
            ob::PlannerStatus status = planner->solve(ptc);
            double elapsed = seconds();
            json row;
            row["query"] = q;
            row["run"] = run;
            row["time_s"] = elapsed;
            row["iterations"] = iterations.getTimesCalled();
            row["collision_checks"] = g_checks.load();
            bool exact = status == ob::PlannerStatus::EXACT_SOLUTION && pdef->hasExactSolution();
            bool approximate = status == ob::PlannerStatus::APPROXIMATE_SOLUTION;
            row["status"] = exact ? "exact" : (approximate ? "approximate" : "none");
            ob::PlannerData data(si);
            planner->getPlannerData(data);
            row["states"] = data.numVertices();
            json path = json::array();
            if (exact || approximate) {
                auto *geometric = pdef->getSolutionPath()->as<og::PathGeometric>();
                path = path_of(*geometric, space);
                row["cost"] = geometric->length();
            } else {
                row["cost"] = nullptr;
            }
            row["path"] = path;
            row["improvements"] = improvements;
            out.push_back(row);
        }
    }
    tm_checker_free(checker);
    print(out, nullptr);
    return 0;
}
