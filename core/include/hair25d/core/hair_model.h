// The 2.5D hair model (DESIGN.md data model): strands with completed shapes,
// textures, meshes and skeletons, their depth relations, and the filled
// background. Written to and read from a model folder (model_io.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hair25d/core/annotation.h"
#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"
#include "hair25d/core/tri_mesh.h"

namespace hair25d {

// A tree of skeleton nodes: node 0 is the root, parent[i] < 0 only for the root.
struct Skeleton {
  Polyline nodes;           // pixels
  std::vector<int> parent;  // #nodes, index of the parent node, -1 for the root
  std::vector<int> tips;    // indices of tip nodes (leaves)
};

// Simulation parameters of one strand (paper §6.1).
struct StrandPhysics {
  double stiffness = 1.0;  // γ, bending stiffness
  double tau0 = 1.0;       // τ₀, base rotation rate
  double lambda = 1.0;     // λ, τ = τ₀ d^λ
  double damping = 0.1;    // fraction of angular velocity lost per second
  double gravity = 1.0;    // scale of gravity, 0 = none
};

struct Strand {
  int id = 0;
  std::string name;
  std::vector<int> regions;              // source region ids (stroke / annotation labels)
  int depth = 0;                         // drawing order: 0 is drawn first (back-most)
  Polyline outline;                      // completed shape, one closed polygon, pixels
  Image texture;                         // RGBA, completed colours, transparent outside
  Eigen::Vector2i texture_origin{0, 0};  // image pixel of texture(0, 0)
  TriMesh2 mesh;                         // deformation mesh of the completed shape
  Skeleton skeleton;
  StrandPhysics physics;
};

// What the layering measured for an `equal` between two regions: its
// confidence, which RegionRelation::score (whose sign means an order) cannot
// carry. Completion refuses weak ones where the paint says two strands.
struct EqualEvidence {
  // The same-depth model's length-weighted mean log-odds of one depth
  // (positive: one depth), over the pair's occluding boundaries, or, for a
  // pair equal because its common boundary is mostly open, over the open ones.
  double log_odds = 0.0;
  bool open = false;           // equal because most of its common boundary is open
  double open_fraction = 0.0;  // share of the common boundary with no occluding line
};

// The depth relation between two regions with its score (positive = a on top).
struct RegionRelation {
  int a = 0;
  int b = 0;
  Relation relation = Relation::kEqual;  // where a lies relative to b
  double score = 0.0;
  bool user_fixed = false;  // set by the user, kept when re-solving
  // Flipped to agree with the drawing order: by layering, to break a cycle of
  // stronger relations; by the model, where the strands' order (relations
  // summed over their pieces) disagrees. `score` keeps its original sign.
  bool overridden = false;
  // Set by the layering on the `equal`s it measured (none on orders, the
  // user's relations, pairs related by their drawing order alone).
  std::optional<EqualEvidence> equal_evidence{};
};

struct HairModel {
  int width = 0;
  int height = 0;
  Image image;       // the input drawing
  Image background;  // the drawing with the hair removed and filled
  std::vector<Strand> strands;
  std::vector<RegionRelation> relations;
  std::optional<Vec2> head_center;
};

}  // namespace hair25d
