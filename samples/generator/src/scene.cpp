#include "scene.h"

#include <algorithm>
#include <cmath>

#include "layout.h"

namespace hair25d::generator {

namespace {

// Fisher–Yates with our own integer draws (std::shuffle's use of the engine is
// implementation-defined).
template <class T>
void shuffle(std::vector<T>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) {
    std::swap(v[i - 1], v[static_cast<std::size_t>(rng.uniform_int(0, static_cast<int>(i) - 1))]);
  }
}

int share(int total, double fraction) {
  return std::clamp(static_cast<int>(std::lround(total * fraction)), 0, total);
}

// Tilts the whole head about its centre: every polygon and line of every shape.
void rotate_scene(Scene& scene, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const Vec2 o = scene.head_center;
  auto turn = [&](Vec2& p) {
    const Vec2 d = p - o;
    p = o + Vec2(c * d.x() - s * d.y(), s * d.x() + c * d.y());
  };
  auto turn_all = [&](Polyline& line) {
    for (Vec2& p : line) turn(p);
  };
  for (Shape& shape : scene.shapes) {
    turn_all(shape.outline);
    turn_all(shape.band);
    for (Polyline& l : shape.inner_lines) turn_all(l);
    for (Polyline& l : shape.hidden_lines) turn_all(l);
    for (FilledEllipse& e : shape.decorations) {
      turn(e.centre);
      e.angle += angle;
    }
    if (shape.geometry) {
      turn_all(shape.geometry->centre);
      turn_all(shape.geometry->left);
      turn_all(shape.geometry->right);
    }
  }
}

}  // namespace

Scene make_scene(const Options& options, Rng& rng) {
  Scene scene;
  scene.width = options.width;
  scene.height = options.height;
  scene.line_width = options.line_width;
  scene.shading = options.shading;
  const Palette pal = make_palette(options, rng);
  scene.background = pal.background;
  scene.line_colour = pal.line;
  const Head head = make_head(options, rng);
  scene.head_center = head.centre;
  scene.tone_period = rng.uniform(4.5, 8.0) * std::max(1.0, options.line_width / 3.0);
  scene.tone_angle = rng.uniform(0.3, 1.2);

  // How the strands are spent: one back mass, often a cap over the crown, then
  // tails, strands hidden behind the face, bangs under the cap, and the front.
  const int n = options.strand_count;
  const bool cap = n >= 3 && rng.chance(0.8);
  int rest = n - 1 - (cap ? 1 : 0);
  int tails_per_side = 0;
  if (rest >= 6 && rng.chance(0.35)) tails_per_side = rng.uniform_int(1, std::min(3, rest / 6));
  rest -= 2 * tails_per_side;
  const int behind = share(rest, rng.uniform(0.05, 0.2));
  const int under = cap ? share(rest - behind, rng.uniform(0.1, 0.3)) : 0;
  const int front = rest - behind - under;
  const int side_front = share(front, rng.uniform(0.15, 0.4));
  const int bangs = front - side_front;
  const bool body = rng.chance(0.5);

  std::vector<Shape> shapes;
  Rng strands_rng = rng.fork();
  for (int side : {-1, 1}) {
    for (int i = 0; i < tails_per_side; ++i) {
      shapes.push_back(make_strand(StrandKind::kTail, head, pal, options, side, -1.0, strands_rng));
    }
  }
  shapes.push_back(make_back_mass(head, pal, options.height, rng));
  if (tails_per_side > 0 && rng.chance(0.7)) {
    for (int side : {-1, 1}) shapes.push_back(make_tie(head, pal, side, rng));
  }
  if (body) shapes.push_back(make_body(head, pal, options.height, rng));
  for (int i = 0; i < behind; ++i) {
    shapes.push_back(make_strand(StrandKind::kBehindFace, head, pal, options,
                                 strands_rng.chance(0.5) ? 1 : -1, -1.0, strands_rng));
  }
  shapes.push_back(make_face(head, pal, rng));
  for (int i = 0; i < under; ++i) {
    shapes.push_back(make_strand(StrandKind::kUnderCap, head, pal, options, 0,
                                 (i + strands_rng.uniform()) / under, strands_rng));
  }
  if (cap) shapes.push_back(make_cap(head, pal, rng));
  std::vector<Shape> front_shapes;
  for (int i = 0; i < side_front; ++i) {
    front_shapes.push_back(make_strand(StrandKind::kSideFront, head, pal, options,
                                       i % 2 == 0 ? -1 : 1, -1.0, strands_rng));
  }
  for (int i = 0; i < bangs; ++i) {
    front_shapes.push_back(make_strand(StrandKind::kBang, head, pal, options, 0,
                                       (i + strands_rng.uniform()) / bangs, strands_rng));
  }
  shuffle(front_shapes, strands_rng);
  for (Shape& s : front_shapes) shapes.push_back(std::move(s));

  // Strand ids follow the painter's order, so a larger id lies above.
  int strand = 0;
  for (Shape& s : shapes) {
    if (!s.hair) continue;
    s.strand = ++strand;
    if (s.geometry) s.name += std::to_string(s.strand);
  }
  scene.strand_count = strand;
  scene.shapes = std::move(shapes);
  if (rng.chance(0.6)) rotate_scene(scene, rng.uniform(-0.14, 0.14));
  return scene;
}

}  // namespace hair25d::generator
