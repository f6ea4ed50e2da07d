// The arm peer of the benchmark harness: OMPL's RRTConnect (or InformedRRTstar, BITstar) planning a robot arm's group in joint
// space, states checked by FCL on the robot's spheres and the scene's primitives, the same model
// trailmark's ArmChecker checks (xtask/src/bench/ompl_arm/mod.rs writes the input from trailmark's
// Robot, SphereModel and Scene). xtask compiles it with
// `c++ -std=c++17 $(pkg-config --cflags ompl fcl eigen3 nlohmann_json) ... -lompl -lfcl -lccd`.
//
// Usage: ompl-arm-driver < INPUT.json > OUTPUT.json (or ompl-arm-driver INPUT.json).
//
// INPUT, one JSON document:
//   "bounds":    [[lower, upper], ...]      one per group variable (the state's dimensions)
//   "frames":    [{"parent": p, "origin": [x, y, z, qx, qy, qz, qw],
//                  "joint": "fixed" | "revolute" | "prismatic", "axis": [x, y, z],
//                  "variable": v, "multiplier": m, "offset": o, "value": c}, ...]
//                The robot's links in tree order (each after its parent; the root first with
//                parent -1). A frame's pose is parent's pose * origin * motion(value), motion a
//                turn about the axis (revolute) or a shift along it (prismatic); the value is
//                m * q[v] + o when variable v >= 0 (a group joint, or a mimic of one), else c
//                (joints outside the group stay at the start state's value).
//   "spheres":   [{"frame": f, "centre": [x, y, z], "radius": r}, ...]  centre in frame f
//   "self_pairs": [[fa, fb], ...]  the frame pairs whose spheres are tested against each other
//   "obstacles": [{"shape": "box", "half": [x, y, z]} | {"shape": "cylinder", "radius": r,
//                  "half_height": h} | {"shape": "sphere", "radius": r}, each with
//                  "position": [x, y, z], "orientation": [qx, qy, qz, qw] (world frame) and
//                  "allowed_frames": [f, ...] (frames allowed to touch it)]
//   "queries":   [{"start": [...], "goal": [...]}, ...]
//   "planner": "rrt_connect" (the default) | "informed_rrt_star" | "bit_star" | "prm_star": the
//                optimizing planners minimise the path's length (PathLengthOptimizationObjective,
//                no cost threshold) and run until the time limit; "prm_star" only builds a
//                roadmap of "roadmap_size" milestones (or until the time limit) per run, with
//                the run's "time_s" the build's, "vertices" and "edges" the roadmap's and no path,
//   "runs": runs per query, "seed": OMPL's global seed (set once), "time_limit_s": per run,
//   "range": the tree planners' range (0: OMPL's default; BITstar has none), "resolution": the longest segment a motion
//   is checked without a state in between, in joint-space units (OMPL's longest valid segment;
//   given to OMPL as a fraction of the space's extent), "simplify": whether to simplify.
//   "states":    optional, [[q...], ...]: states only to check, answered in "valid".
//
// OUTPUT, one JSON document:
//   {"ompl_version", "fcl_version",
//    "runs": [{"query", "run", "status": "exact" | "approximate" | "none", "time_s", "checks",
//              "vertices", "length", "path": [[q...], ...],
//              with "simplify": "simplify_time_s", "simplify_checks", "simplified_length",
//              "simplified": [[q...], ...]}, ...],
//    "valid": [bool, ...], "check_time_s"}  (for "states")
// "time_s" is the wall time of SimpleSetup::solve, "checks" the state validity checks made in
// it (OMPL's DiscreteMotionValidator checks a motion as states, so motions count as the states
// they were checked at), "vertices" the planner's tree vertices; "length" is the path's length
// in joint space.
//
// Collision checking. The robot is one fcl::Sphered collision object per sphere, the scene one
// fcl::Boxd, fcl::Cylinderd or fcl::Sphered object per primitive. Each is kept in a
// DynamicAABBTreeCollisionManager (the broadphase MoveIt's FCL plugin keeps the world in): the
// world's tree is built once; per state the robot's objects are moved to their forward
// kinematics pose (Eigen) and its tree refitted. A state is valid iff the robot's tree against
// the world's finds no pair that fcl::collide reports in contact (pairs of an obstacle and a
// frame allowed to touch it passed over), and the robot's tree against itself finds no pair of
// spheres of a self pair of frames in contact. Each query stops at the first contact. FCL's
// narrow phase for these primitives (sphere-sphere, sphere-box, sphere-cylinder) is exact, with
// touching counted as contact, as trailmark's checker counts it.
//
// Simplification: SimpleSetup::simplifySolution(time_limit_s), as MoveIt simplifies: OMPL's
// PathSimplifier (shortcuts, vertex reduction, smoothing) for at most the time limit.

#include <chrono>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/config.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <nlohmann/json.hpp>
#include <ompl/base/PlannerData.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/config.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

namespace ob = ompl::base;
namespace og = ompl::geometric;
using json = nlohmann::json;

namespace {

enum class JointKind { Fixed, Revolute, Prismatic };

// A link's frame and the joint above it.
struct Frame {
    int parent = -1;
    Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
    JointKind kind = JointKind::Fixed;
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    int variable = -1;
    double multiplier = 1.0, offset = 0.0, value = 0.0;
};

// What an FCL object is: a robot sphere or an obstacle, and its index.
struct Tag {
    bool obstacle;
    int index;
};

Eigen::Isometry3d pose_of(const std::vector<double> &p, const std::vector<double> &q) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translate(Eigen::Vector3d(p.at(0), p.at(1), p.at(2)));
    pose.rotate(Eigen::Quaterniond(q.at(3), q.at(0), q.at(1), q.at(2)).normalized());
    return pose;
}

Eigen::Vector3d vector_of(const json &v) {
    auto x = v.get<std::vector<double>>();
    return Eigen::Vector3d(x.at(0), x.at(1), x.at(2));
}

// The robot's spheres among the scene's primitives, as the file's top says.
class ArmWorld {
public:
    explicit ArmWorld(const json &input) {
        for (const auto &f : input.at("frames")) {
            Frame frame;
            frame.parent = f.at("parent").get<int>();
            auto o = f.at("origin").get<std::vector<double>>();
            frame.origin = pose_of({o.at(0), o.at(1), o.at(2)}, {o.at(3), o.at(4), o.at(5), o.at(6)});
            std::string joint = f.at("joint").get<std::string>();
            frame.kind = joint == "revolute"    ? JointKind::Revolute
                         : joint == "prismatic" ? JointKind::Prismatic
                                                : JointKind::Fixed;
            frame.axis = vector_of(f.at("axis")).normalized();
            frame.variable = f.value("variable", -1);
            frame.multiplier = f.value("multiplier", 1.0);
            frame.offset = f.value("offset", 0.0);
            frame.value = f.value("value", 0.0);
            if (frame.parent >= static_cast<int>(frames_.size())) {
                throw std::runtime_error("a frame before its parent");
            }
            frames_.push_back(frame);
        }
        const size_t n = frames_.size();
        poses_.resize(n);
        self_.assign(n * n, 0);
        for (const auto &p : input.at("self_pairs")) {
            size_t a = p.at(0).get<size_t>(), b = p.at(1).get<size_t>();
            self_.at(a * n + b) = self_.at(b * n + a) = 1;
        }
        for (const auto &s : input.at("spheres")) {
            sphere_frame_.push_back(s.at("frame").get<int>());
            centre_.push_back(vector_of(s.at("centre")));
            auto shape = std::make_shared<fcl::Sphered>(s.at("radius").get<double>());
            robot_.push_back(std::make_unique<fcl::CollisionObjectd>(shape));
        }
        for (const auto &o : input.at("obstacles")) {
            std::string shape = o.at("shape").get<std::string>();
            std::shared_ptr<fcl::CollisionGeometryd> geometry;
            if (shape == "box") {
                geometry = std::make_shared<fcl::Boxd>(2.0 * vector_of(o.at("half")));
            } else if (shape == "cylinder") {
                geometry = std::make_shared<fcl::Cylinderd>(o.at("radius").get<double>(),
                                                            2.0 * o.at("half_height").get<double>());
            } else if (shape == "sphere") {
                geometry = std::make_shared<fcl::Sphered>(o.at("radius").get<double>());
            } else {
                throw std::runtime_error("unknown obstacle shape " + shape);
            }
            Eigen::Isometry3d pose = pose_of(o.at("position").get<std::vector<double>>(),
                                             o.at("orientation").get<std::vector<double>>());
            world_.push_back(std::make_unique<fcl::CollisionObjectd>(geometry, pose.rotation(),
                                                                     pose.translation()));
            std::vector<char> allowed(n, 0);
            for (const auto &f : o.value("allowed_frames", json::array())) {
                allowed.at(f.get<size_t>()) = 1;
            }
            allowed_.push_back(allowed);
        }
        tags_.reserve(robot_.size() + world_.size());
        for (size_t i = 0; i < robot_.size(); ++i) {
            tags_.push_back({false, static_cast<int>(i)});
            robot_[i]->setUserData(&tags_.back());
            robot_manager_.registerObject(robot_[i].get());
        }
        for (size_t i = 0; i < world_.size(); ++i) {
            tags_.push_back({true, static_cast<int>(i)});
            world_[i]->computeAABB();
            world_[i]->setUserData(&tags_.back());
            world_manager_.registerObject(world_[i].get());
        }
        world_manager_.setup();
        robot_manager_.setup();
    }

    // Whether the robot at the group's values `q` touches nothing it is checked against.
    bool valid(const double *q) {
        ++checks;
        for (size_t f = 0; f < frames_.size(); ++f) {
            const Frame &frame = frames_[f];
            double v = frame.variable >= 0 ? frame.multiplier * q[frame.variable] + frame.offset
                                           : frame.value;
            Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
            if (frame.kind == JointKind::Revolute) {
                motion.rotate(Eigen::AngleAxisd(v, frame.axis));
            } else if (frame.kind == JointKind::Prismatic) {
                motion.translate(v * frame.axis);
            }
            poses_[f] = frame.parent < 0 ? frame.origin * motion : poses_[frame.parent] * frame.origin * motion;
        }
        for (size_t s = 0; s < robot_.size(); ++s) {
            robot_[s]->setTranslation(poses_[sphere_frame_[s]] * centre_[s]);
            robot_[s]->computeAABB();
        }
        robot_manager_.update();
        Query query{this, false};
        robot_manager_.collide(&world_manager_, &query, &ArmWorld::contact);
        if (!query.hit) {
            robot_manager_.collide(&query, &ArmWorld::contact);
        }
        return !query.hit;
    }

    // State validity checks made.
    uint64_t checks = 0;

private:
    struct Query {
        const ArmWorld *world;
        bool hit;
    };

    // The broadphase's callback: whether the pair is checked and in contact (which ends the
    // query).
    static bool contact(fcl::CollisionObjectd *a, fcl::CollisionObjectd *b, void *data) {
        auto *query = static_cast<Query *>(data);
        const ArmWorld &w = *query->world;
        const Tag *ta = static_cast<const Tag *>(a->getUserData());
        const Tag *tb = static_cast<const Tag *>(b->getUserData());
        if (ta->obstacle) {
            std::swap(ta, tb);
        }
        if (ta->obstacle) {
            return false;
        }
        int fa = w.sphere_frame_[ta->index];
        if (tb->obstacle) {
            if (w.allowed_[tb->index][fa]) {
                return false;
            }
        } else {
            int fb = w.sphere_frame_[tb->index];
            if (!w.self_[fa * w.frames_.size() + fb]) {
                return false;
            }
        }
        fcl::CollisionRequestd request;
        fcl::CollisionResultd result;
        if (fcl::collide(a, b, request, result) > 0) {
            query->hit = true;
        }
        return query->hit;
    }

    std::vector<Frame> frames_;
    std::vector<Eigen::Isometry3d> poses_;
    std::vector<char> self_;
    std::vector<int> sphere_frame_;
    std::vector<Eigen::Vector3d> centre_;
    std::vector<std::vector<char>> allowed_;
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> robot_, world_;
    std::vector<Tag> tags_;
    fcl::DynamicAABBTreeCollisionManagerd robot_manager_, world_manager_;
};

class Validity : public ob::StateValidityChecker {
public:
    Validity(const ob::SpaceInformationPtr &si, ArmWorld *world) : ob::StateValidityChecker(si), world_(world) {}

    bool isValid(const ob::State *state) const override {
        return world_->valid(state->as<ob::RealVectorStateSpace::StateType>()->values);
    }

private:
    ArmWorld *world_;
};

json states_of(const og::PathGeometric &path, unsigned dims) {
    json out = json::array();
    for (std::size_t i = 0; i < path.getStateCount(); ++i) {
        const double *q = path.getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
        out.push_back(std::vector<double>(q, q + dims));
    }
    return out;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

json run(const json &input) {
    const auto bounds = input.at("bounds").get<std::vector<std::vector<double>>>();
    const unsigned dims = bounds.size();
    auto space = std::make_shared<ob::RealVectorStateSpace>(dims);
    ob::RealVectorBounds box(dims);
    for (unsigned i = 0; i < dims; ++i) {
        box.setLow(i, bounds[i].at(0));
        box.setHigh(i, bounds[i].at(1));
    }
    space->setBounds(box);
    ArmWorld world(input);
    og::SimpleSetup setup(space);
    auto si = setup.getSpaceInformation();
    setup.setStateValidityChecker(std::make_shared<Validity>(si, &world));
    double resolution = input.at("resolution").get<double>();
    space->setLongestValidSegmentFraction(resolution / space->getMaximumExtent());
    const std::string name = input.value("planner", std::string("rrt_connect"));
    const double range = input.value("range", 0.0);
    if (name == "rrt_connect") {
        auto planner = std::make_shared<og::RRTConnect>(si);
        if (range > 0.0) {
            planner->setRange(range);
        }
        setup.setPlanner(planner);
    } else if (name == "informed_rrt_star") {
        auto planner = std::make_shared<og::InformedRRTstar>(si);
        if (range > 0.0) {
            planner->setRange(range);
        }
        setup.setPlanner(planner);
    } else if (name == "bit_star") {
        setup.setPlanner(std::make_shared<og::BITstar>(si));
    } else if (name == "prm_star") {
        setup.setPlanner(std::make_shared<og::PRMstar>(si));
    } else {
        throw std::runtime_error("unknown planner " + name);
    }
    if (name != "rrt_connect") {
        setup.setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
    }
    setup.setup();

    json out;
    out["ompl_version"] = OMPL_VERSION;
    out["fcl_version"] = FCL_VERSION;
    out["runs"] = json::array();
    const double limit = input.at("time_limit_s").get<double>();
    const unsigned runs = input.value("runs", 1u);
    const bool simplify = input.value("simplify", false);
    const unsigned long roadmap_size = input.value("roadmap_size", 0UL);
    const auto &queries = input.at("queries");
    for (size_t k = 0; k < queries.size(); ++k) {
        auto start = queries[k].at("start").get<std::vector<double>>();
        auto goal = queries[k].at("goal").get<std::vector<double>>();
        if (start.size() != dims || goal.size() != dims) {
            throw std::runtime_error("a query's start or goal of another dimension than the bounds");
        }
        ob::ScopedState<> a(space), b(space);
        for (unsigned i = 0; i < dims; ++i) {
            a[i] = start[i];
            b[i] = goal[i];
        }
        for (unsigned r = 0; r < runs; ++r) {
            setup.clear();
            setup.setStartAndGoalStates(a, b);
            world.checks = 0;
            if (name == "prm_star") {
                // The roadmap alone: PRMstar's solve would go on growing it until the time limit
                // (its objective is never satisfied), so only the build is timed.
                setup.setup();
                auto prm = setup.getPlanner()->as<og::PRMstar>();
                auto clock = std::chrono::steady_clock::now();
                prm->growRoadmap(ob::plannerOrTerminationCondition(
                    ob::PlannerTerminationCondition(
                        [prm, roadmap_size] { return prm->milestoneCount() >= roadmap_size; }),
                    ob::timedPlannerTerminationCondition(limit)));
                json row;
                row["query"] = k;
                row["run"] = r;
                row["time_s"] = seconds_since(clock);
                row["checks"] = world.checks;
                row["vertices"] = prm->milestoneCount();
                row["edges"] = prm->edgeCount();
                row["status"] = "none";
                row["path"] = json::array();
                out["runs"].push_back(row);
                continue;
            }
            auto clock = std::chrono::steady_clock::now();
            ob::PlannerStatus status = setup.solve(limit);
            double time = seconds_since(clock);
            json row;
            row["query"] = k;
            row["run"] = r;
            row["time_s"] = time;
            row["checks"] = world.checks;
            ob::PlannerData data(si);
            setup.getPlannerData(data);
            row["vertices"] = data.numVertices();
            bool found = status == ob::PlannerStatus::EXACT_SOLUTION ||
                         status == ob::PlannerStatus::APPROXIMATE_SOLUTION;
            row["status"] = status == ob::PlannerStatus::EXACT_SOLUTION         ? "exact"
                            : status == ob::PlannerStatus::APPROXIMATE_SOLUTION ? "approximate"
                                                                               : "none";
            row["path"] = json::array();
            if (found) {
                og::PathGeometric &path = setup.getSolutionPath();
                row["path"] = states_of(path, dims);
                row["length"] = path.length();
                if (simplify) {
                    world.checks = 0;
                    setup.simplifySolution(limit);
                    row["simplify_time_s"] = setup.getLastSimplificationTime();
                    row["simplify_checks"] = world.checks;
                    og::PathGeometric &simple = setup.getSolutionPath();
                    row["simplified"] = states_of(simple, dims);
                    row["simplified_length"] = simple.length();
                }
            }
            out["runs"].push_back(row);
        }
    }
    if (input.contains("states")) {
        json valid = json::array();
        auto clock = std::chrono::steady_clock::now();
        for (const auto &s : input.at("states")) {
            auto q = s.get<std::vector<double>>();
            if (q.size() != dims) {
                throw std::runtime_error("a state of another dimension than the bounds");
            }
            valid.push_back(world.valid(q.data()));
        }
        out["check_time_s"] = seconds_since(clock);
        out["valid"] = valid;
    }
    return out;
}

}  // namespace

int main(int argc, char **argv) {
    json input;
    try {
        if (argc > 1) {
            std::ifstream file(argv[1]);
            if (!file) {
                std::cerr << "cannot read " << argv[1] << "\n";
                return 2;
            }
            input = json::parse(file);
        } else {
            input = json::parse(std::cin);
        }
    } catch (const std::exception &e) {
        std::cerr << "bad input: " << e.what() << "\n";
        return 2;
    }
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ompl::RNG::setSeed(input.value("seed", 1UL));
    try {
        std::cout << run(input).dump() << "\n";
    } catch (const std::exception &e) {
        std::cerr << "ompl-arm-driver: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
