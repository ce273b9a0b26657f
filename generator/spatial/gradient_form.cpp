#include "spatial/gradient_form.hpp"

#include <algorithm>

#include "spatial/planar_tree.hpp"

namespace eomgen {

namespace {

// The loops run as fast as straight-line code or faster beyond 8 velocities: jacobian_state, g++ -O2
// -march=native, the fastest of 93 batches, the two forms' headers timed in turn: trees of oblique
// hinges in tests/benchmarks/robot_models.py's branching, 9 joints 2.67 µs against 2.93, 13 joints
// 4.58 against 4.82, 21 joints 8.5 against 9.8; the 7-joint arm, whose axes and ±90° turns
// straight-line code folds, 1.99 against 1.47. Their header is smaller at every size (the 21
// joints' 558 KB against 1089 KB). Joints that follow another's coordinate add links but no
// velocities, and the straight-line sums fold them: Pinocchio's panda.urdf (9 joints, its second
// finger a follower: 8 velocities) 2.0 µs against the loops' 2.9, tests/crosscheck's gantry hand
// with its fingers' outer joints followers (11 joints, 5 velocities) 3.8 rhs against 4.5. So the
// crossover counts velocities. Below a free joint (its motion straight-line, the hinges in the
// loops) the two forms run within a few per cent of each other from 9 velocities on (a free torso
// and two legs of 3 hinges: 2.16 µs against 2.10; of 8: 4.9 against 5.05; tests/crosscheck's
// quadruped, 18 velocities: 6.8 against 6.8), while the header is a third smaller (the
// quadruped's 307 KB against 718 KB, g++ 4 s against 18 s) and, for a floating humanoid,
// several times smaller (Talos, 38 velocities: 1.17 MB against 3.3 MB, g++ 18 s against 386 s,
// jacobian_state 28 µs against 52).
constexpr std::size_t loops_beyond_velocities = 8;
// Straight-line code grows with the pairs of a joint and one above it (or itself), the loops do not:
// a shallow tree of many velocities keeps straight-line code. Example-robot-data's fixed-base
// quadrupeds (12 velocities in four legs of three, 24 pairs; g++ -O2, one timing program per form)
// ran jacobian_state in 2.27 µs against the loops' 3.92 (A1), 2.34 against 3.71 (Laikago), 2.88
// against 3.48 (Solo12). From about 40 pairs on, trees of oblique axes run faster in the loops
// (the gantry and coupled hands of tests/crosscheck/models/, 39 pairs: 3.70 µs and 3.46 in the
// loops against 3.74 and 3.85; the Allegro hand, 40: 4.58 against 4.81), so the cut is below them.
constexpr std::size_t loops_beyond_pairs = 32;
// A tree that moves in one plane (spatial/planar_tree.hpp) folds three of every six-vector's
// components, so that its straight-line code stays smaller and faster much longer. Measured with
// tests/benchmarks/robot_sweep.py (g++ -O2, jacobian_state / rhs, straight-line against loops):
// dm_control's cheetah and walker (9 velocities, 36 pairs) 3.1 against 10.6 and 3.3 against 10.8;
// a planar chain on slides x, z and a hinge, of 10 and 16 more hinges (91 and 190 pairs) 4.5 against
// 11.0 and 6.2 against 11.6, its header 204 KB against 158 and 378 against 269, g++ 9.5 s against
// 6.8 and 16 against 9.
constexpr std::size_t loops_beyond_pairs_in_a_plane = 200;
// Below the root, a ball joint's link has three columns and four directions (its quaternion's), which
// straight-line code folds with its constant axes and the loops do not: chains of ball joints with
// full inertias (jacobian_state, g++ -O2, one core, the fastest of 201 batches, the two forms' headers
// in one program) of 4, 6 and 8 (90, 189 and 324 pairs) ran 15 %, 10 % and 12 % slower in the
// loops (3.41 µs against 2.96, 6.70 against 6.20, 15.5 against 14.1), of 10 and 12 (495 and 702)
// 5 % and 8 % faster (19.0 against 20.1, 28.9 against 31.4); tests/crosscheck/mjcf/ball_ragdoll.xml
// without its wrists and right ankle (seven balls and four hinges below a free root, 310 pairs)
// 16 % slower (12.6 against 10.9).
// Straight-line code costs its build time all the same: the ragdoll's header 1.57 MB against 646 KB
// and g++ -O2 about 130 s against 15; the 12 balls' 2.35 MB against 853 KB, 353 s against 25.
constexpr std::size_t loops_beyond_pairs_with_ball_joints = 400;
// The pairs misjudge a tree whose straight-line code folds: Gymnasium's pusher.xml (a PR2 arm of
// seven hinges about its links' own x, y and z axes, and two bodies on two slides each: 11
// velocities, 34 pairs) ran jacobian_state in 1.08 µs in straight-line code against the loops'
// 2.07–2.14 (g++ -O2, one core, the fastest of 201 batches, both headers in turn), its header 289 KB
// against 135 and g++ -O2 of rhs and jacobian_state 4.0 s against 1.8. So beyond the cut a tree
// of up to 64 pairs keeps straight-line code where its gradient, counted before it is written
// (symbolic/expression_cost.hpp), is no longer than the seven-joint arm's, which issue 38's limits
// on header and build time were set for (8,425 operations so counted; the pusher's 8,136). The
// gantry and coupled hands (39 pairs, 10,173 and 10,231) and three legs of five hinges (45,
// 17,851) keep the loops: straight-line code would run their jacobian_state faster too (the hands
// 1.7 µs against 2.6–3.7 the same day) but their headers would be 449 KB and build in 9 s, not 2.
constexpr std::size_t written_out_when_short_up_to_pairs = 64;
constexpr long written_out_when_short_up_to_operations = 9000;

// the pairs of a link and a link at or above it, weighted by their joints' velocities
std::size_t joint_pairs(const std::vector<TreeLink>& links) {
  std::size_t pairs = 0;
  for (std::size_t k = 0; k < links.size(); ++k)
    for (int up = int(k); up >= 0; up = links[std::size_t(up)].parent)
      pairs += links[k].columns.size() * links[std::size_t(up)].columns.size();
  return pairs;
}

}  // namespace

bool beyond_straight_line_cut(const std::vector<TreeLink>& links, std::size_t velocities) {
  std::size_t pairs = joint_pairs(links);
  // a root's joint of several velocities (a floating base, a free object beside it) is straight-line
  // code in the loops too
  bool ball_below_root = std::any_of(links.begin(), links.end(), [](const TreeLink& l) { return l.parent >= 0 && l.columns.size() > 1; });
  bool long_tree = ball_below_root ? pairs > loops_beyond_pairs_with_ball_joints
                                   : pairs > loops_beyond_pairs && (pairs > loops_beyond_pairs_in_a_plane || !moves_in_a_plane(links));
  return velocities > loops_beyond_velocities && long_tree;
}

bool worth_counting_straight_line(const std::vector<TreeLink>& links) {
  return joint_pairs(links) <= written_out_when_short_up_to_pairs;
}

bool short_enough_for_straight_line(long operations) { return operations <= written_out_when_short_up_to_operations; }

}  // namespace eomgen
