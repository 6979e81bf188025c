#include "layout.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hair25d::generator {

namespace {

constexpr double kPi = std::numbers::pi;

Colour hsv(double h, double s, double v) {
  h = (h - std::floor(h)) * 6.0;
  const int i = static_cast<int>(h) % 6;
  const double f = h - std::floor(h);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (i) {
    case 0:
      return {v, t, p};
    case 1:
      return {q, v, p};
    case 2:
      return {p, v, t};
    case 3:
      return {p, q, v};
    case 4:
      return {t, p, v};
    default:
      return {v, p, q};
  }
}

Colour clamp01(const Colour& c) { return c.cwiseMax(0.0).cwiseMin(1.0); }

Vec2 rotate(const Vec2& v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

void append_bezier(Polyline& out, const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d,
                   int n) {
  const Vec2 p[4] = {a, b, c, d};
  for (int i = 1; i <= n; ++i) out.push_back(bezier_point(p, static_cast<double>(i) / n));
}

// A per-strand variation of the hair colour: most strands near it, a few
// clearly lighter or tinted, as painted highlights in cel-shaded hair.
Colour vary(const Colour& base, Rng& rng) {
  if (rng.chance(0.1)) {
    return clamp01(base * rng.uniform(1.05, 1.25) + Colour(0.05, 0.03, -0.02));
  }
  return clamp01(base * rng.uniform(0.92, 1.08));
}

}  // namespace

Palette make_palette(const Options& options, Rng& rng) {
  Palette p;
  p.hair = hsv(rng.uniform(), rng.uniform(0.12, 0.75), rng.uniform(0.35, 0.92));
  p.skin =
      clamp01(Colour(1.0, 0.92, 0.84) +
              Colour(rng.uniform(-0.03, 0.0), rng.uniform(-0.04, 0.02), rng.uniform(-0.05, 0.03)));
  p.clothes = hsv(rng.uniform(), rng.uniform(0.2, 0.8), rng.uniform(0.3, 0.9));
  p.eyes = hsv(rng.uniform(), rng.uniform(0.3, 0.8), rng.uniform(0.15, 0.45));
  p.background = hsv(rng.uniform(), rng.uniform(0.03, 0.25), rng.uniform(0.82, 0.98));
  p.line = options.coloured_lines ? Colour(p.hair * rng.uniform(0.2, 0.35))
                                  : Colour(Colour::Constant(rng.uniform(0.03, 0.12)));
  if (options.shading == Shading::kScreentone) {
    // Grey manga: white paper, white skin, hair given by its dot density.
    p.hair = Colour::Constant(1.0);
    p.skin = Colour::Constant(1.0);
    p.clothes = Colour::Constant(rng.uniform(0.75, 1.0));
    p.eyes = Colour::Constant(rng.uniform(0.1, 0.3));
    p.background = Colour::Constant(rng.uniform(0.94, 1.0));
    p.line = Colour::Constant(rng.uniform(0.0, 0.08));
  }
  if (options.dark_hair) {
    // Black or dark-haired characters: paint about as dark as the ink, so
    // against the darkest strands the lines show in hue only (saturated
    // paint, grey ink), or in grey manga in a small step from a dark fill.
    // A third are drawn on a backdrop as dark as the hair. Drawn after everything else, so without
    // the option the random numbers, and the drawing, are those of before it existed.
    p.hair = options.shading == Shading::kScreentone
                 ? Colour(Colour::Constant(rng.uniform(0.15, 0.3)))
                 : hsv(rng.uniform(), rng.uniform(0.45, 0.85), rng.uniform(0.15, 0.35));
    if (options.coloured_lines) p.line = p.hair * rng.uniform(0.2, 0.35);
    if (rng.chance(1.0 / 3.0)) p.background = clamp01(p.hair * rng.uniform(0.8, 1.1));
  }
  return p;
}

Head make_head(const Options& options, Rng& rng) {
  const double w = options.width, h = options.height, m = std::min(w, h);
  Head head;
  head.radius = m * rng.uniform(0.17, 0.25);
  const double r = head.radius;
  double cy = h * rng.uniform(0.33, 0.42);
  cy = std::max(cy, 1.4 * r + 0.02 * h);  // keep the top of the hair in the picture
  head.centre = {w * (0.5 + rng.uniform(-0.06, 0.06)), cy};
  head.face_centre = head.centre + Vec2(r * rng.uniform(-0.04, 0.04), r * rng.uniform(0.2, 0.3));
  head.face_radii = {r * rng.uniform(0.72, 0.85), r * rng.uniform(0.88, 1.0)};
  head.face_angle = rng.uniform(-0.08, 0.08);
  // Few strands are drawn as broad locks, many as thinner ones.
  head.strand_scale = std::clamp(
      rng.uniform(0.85, 1.35) / std::sqrt(std::max(1.0, options.strand_count / 16.0)), 0.55, 1.35);
  return head;
}

Shape make_back_mass(const Head& head, const Palette& pal, int image_height, Rng& rng) {
  const double r = head.radius, cx = head.centre.x(), cy = head.centre.y();
  const double rb = r * rng.uniform(1.12, 1.3), squash = rng.uniform(1.0, 1.1);
  const double bottom = std::min(cy + r * rng.uniform(0.9, 3.2), image_height + 0.3 * r);
  const double flare = rng.uniform(0.92, 1.35);
  Shape s;
  s.name = "back";
  s.colour = clamp01(pal.hair * rng.uniform(0.78, 0.95));
  s.tone = rng.uniform(0.35, 0.55);
  s.band_level = rng.uniform(0.45, 0.75);
  for (int i = 0; i <= 40; ++i) {
    const double a = kPi + kPi * i / 40;
    s.outline.emplace_back(cx + rb * std::cos(a), cy + rb * squash * std::sin(a));
  }
  const Vec2 right_top(cx + rb, cy), left_top(cx - rb, cy);
  const Vec2 right_bottom(cx + rb * flare, bottom);
  Vec2 left_bottom(cx - rb * flare, bottom);
  append_bezier(s.outline, right_top, right_top + Vec2(0, (bottom - cy) * 0.4),
                right_bottom - Vec2(0, (bottom - cy) * 0.3), right_bottom, 12);
  const int style = rng.uniform_int(0, 2);
  if (style == 0) {  // zigzag ends of locks
    const int teeth = rng.uniform_int(3, 7);
    const double amp = r * rng.uniform(0.15, 0.4);
    for (int j = 1; j < 2 * teeth; ++j) {
      const double u = static_cast<double>(j) / (2 * teeth);
      const double y = (j % 2 == 1) ? bottom - amp * rng.uniform(0.7, 1.0) : bottom;
      s.outline.emplace_back(right_bottom.x() + (left_bottom.x() - right_bottom.x()) * u,
                             y + rng.uniform(-0.05, 0.05) * r);
    }
  } else if (style == 1) {  // rounded bob
    const double sag = r * rng.uniform(0.1, 0.5);
    append_bezier(s.outline, right_bottom, right_bottom + Vec2(-0.3 * rb, sag),
                  left_bottom + Vec2(0.3 * rb, sag), left_bottom, 24);
    s.outline.pop_back();
  } else {  // a straight cut, slightly tilted
    left_bottom.y() += rng.uniform(-0.2, 0.2) * r;
  }
  s.outline.push_back(left_bottom);
  append_bezier(s.outline, left_bottom, left_bottom - Vec2(0, (bottom - cy) * 0.3),
                left_top + Vec2(0, (bottom - cy) * 0.4), left_top, 12);
  s.outline.pop_back();  // the arc starts there
  return s;
}

Shape make_cap(const Head& head, const Palette& pal, Rng& rng) {
  const double r = head.radius, cx = head.centre.x(), cy = head.centre.y();
  const double rc = r * rng.uniform(1.0, 1.1), squash = rng.uniform(1.0, 1.08);
  const double beta = rng.uniform(-0.05, 0.3);
  Shape s;
  s.name = "cap";
  s.colour = vary(pal.hair, rng);
  s.tone = rng.uniform(0.15, 0.4);
  s.band_level = rng.uniform(0.5, 0.8);
  for (int i = 0; i <= 48; ++i) {
    const double a = kPi - beta + (kPi + 2 * beta) * i / 48;
    s.outline.emplace_back(cx + rc * std::cos(a), cy + rc * squash * std::sin(a));
  }
  const Vec2 right_end = s.outline.back(), left_end = s.outline.front();
  const Vec2 parting(cx + r * rng.uniform(-0.3, 0.3), cy + r * rng.uniform(-0.45, -0.1));
  append_bezier(s.outline, right_end, right_end + Vec2(-0.3 * r, rng.uniform(0.05, 0.35) * r),
                parting + Vec2(0.35 * r, rng.uniform(0.0, 0.2) * r), parting, 20);
  append_bezier(s.outline, parting, parting + Vec2(-0.35 * r, rng.uniform(0.0, 0.2) * r),
                left_end + Vec2(0.3 * r, rng.uniform(0.05, 0.35) * r), left_end, 20);
  s.outline.pop_back();  // == left_end, the first point
  return s;
}

Shape make_face(const Head& head, const Palette& pal, Rng& rng) {
  Shape s;
  s.hair = false;
  s.name = "face";
  s.colour = pal.skin;
  s.outline = ellipse_polygon(head.face_centre, head.face_radii, head.face_angle, 120);
  const double r = head.radius;
  const double eye_dx = r * rng.uniform(0.28, 0.38), eye_y = r * rng.uniform(0.05, 0.2);
  const Vec2 eye_radii(r * rng.uniform(0.09, 0.14), r * rng.uniform(0.13, 0.2));
  for (int side : {-1, 1}) {
    const Vec2 c = head.face_centre + Vec2(side * eye_dx, eye_y);
    s.decorations.push_back({c, eye_radii, 0.0, pal.eyes});
    s.decorations.push_back({c + Vec2(-0.3 * eye_radii.x(), -0.35 * eye_radii.y()), eye_radii * 0.3,
                             0.0, Colour(1, 1, 1)});
  }
  return s;
}

Shape make_body(const Head& head, const Palette& pal, int image_height, Rng& rng) {
  const double r = head.radius;
  const Vec2 f = head.face_centre;
  const double neck = r * rng.uniform(0.2, 0.3), shoulder = r * rng.uniform(1.4, 2.0);
  const double neck_bottom = f.y() + head.face_radii.y() + r * rng.uniform(0.15, 0.4);
  const double bottom = std::max(neck_bottom + r, static_cast<double>(image_height) + 10.0);
  Shape s;
  s.hair = false;
  s.name = "body";
  s.colour = pal.clothes;
  s.outline = {{f.x() - neck, f.y()},
               {f.x() - neck, neck_bottom},
               {f.x() - shoulder, neck_bottom + 0.35 * r},
               {f.x() - shoulder * 1.15, bottom},
               {f.x() + shoulder * 1.15, bottom},
               {f.x() + shoulder, neck_bottom + 0.35 * r},
               {f.x() + neck, neck_bottom},
               {f.x() + neck, f.y()}};
  return s;
}

Shape make_tie(const Head& head, const Palette& pal, int side, Rng& rng) {
  const double r = head.radius;
  Shape s;
  s.hair = false;
  s.name = "tie";
  s.colour = pal.clothes;
  // On the edge of the back hair, where the tail comes out from behind it.
  const double a = rng.uniform(0.35, 0.75);
  const Vec2 c = head.centre + r * rng.uniform(1.05, 1.2) * Vec2(side * std::cos(a), -std::sin(a));
  s.outline = ellipse_polygon(c, Vec2(r * rng.uniform(0.1, 0.17), r * rng.uniform(0.12, 0.2)),
                              rng.uniform(-0.6, 0.6), 48);
  return s;
}

Shape make_strand(StrandKind kind, const Head& head, const Palette& pal, const Options& options,
                  int side, double slot, Rng& rng) {
  const double r = head.radius, cx = head.centre.x(), cy = head.centre.y();
  Vec2 root(0, 0), dir(0, 1);
  double length = r, width = 0.2 * r;
  Shape s;
  switch (kind) {
    case StrandKind::kBang:
    case StrandKind::kUnderCap: {
      // Stratified along the crown so bangs spread over the forehead.
      const double u = slot >= 0.0 ? slot : rng.uniform();
      const double a = kPi + 0.3 + (kPi - 0.6) * u;
      const double rho =
          kind == StrandKind::kBang ? r * rng.uniform(0.45, 0.9) : r * rng.uniform(0.3, 0.7);
      root = {cx + rho * std::cos(a), cy + 0.9 * rho * std::sin(a)};
      double tilt = (root.x() - cx) / r * rng.uniform(0.2, 0.9) + rng.uniform(-0.25, 0.25);
      if (rng.chance(0.2)) tilt = -tilt * rng.uniform(1.0, 2.0);  // sweeps across others
      dir = Vec2(tilt, 1.0).normalized();
      length = r * (kind == StrandKind::kBang ? rng.uniform(0.65, 1.4) : rng.uniform(1.0, 1.7));
      width = r * rng.uniform(0.13, 0.32);
      s.name = kind == StrandKind::kBang ? "bang" : "under";
      break;
    }
    case StrandKind::kSideFront:
    case StrandKind::kBehindFace: {
      const double a = side < 0 ? kPi + rng.uniform(-0.3, 0.6) : 2 * kPi - rng.uniform(-0.3, 0.6);
      const double rho = r * rng.uniform(0.8, 1.05);
      root = {cx + rho * std::cos(a), cy + rho * std::sin(a)};
      const double out =
          kind == StrandKind::kSideFront ? rng.uniform(-0.2, 0.4) : -rng.uniform(0.1, 0.5);
      dir = Vec2(side * out, 1.0).normalized();
      length = r * rng.uniform(1.1, 2.6);
      width = r * rng.uniform(0.15, 0.36);
      s.name = kind == StrandKind::kSideFront ? "side" : "behind";
      break;
    }
    case StrandKind::kTail: {
      root = {cx + side * r * rng.uniform(0.65, 0.95), cy - r * rng.uniform(0.45, 0.8)};
      dir = Vec2(side * rng.uniform(0.6, 1.0), rng.uniform(0.2, 0.7)).normalized();
      length = r * rng.uniform(2.0, 3.4);
      width = r * rng.uniform(0.25, 0.5);
      s.name = "tail";
      break;
    }
  }
  StrandSpec spec;
  spec.control[0] = root;
  if (kind == StrandKind::kTail) {
    // Out from the head first, then falling: the end points downwards.
    spec.control[3] =
        root + Vec2(side * r * rng.uniform(0.5, 1.2), length * rng.uniform(0.7, 0.95));
    spec.control[1] = root + dir * length * rng.uniform(0.35, 0.55);
    spec.control[2] = spec.control[3] - Vec2(side * rng.uniform(-0.2, 0.2), 1.0) * length * 0.35;
  } else {
    const double sweep = rng.uniform(-0.35, 0.35);
    spec.control[3] = root + rotate(dir, sweep) * length;
    const Vec2 end_dir = rotate(dir, sweep + rng.uniform(-0.6, 0.6));
    spec.control[1] = root + rotate(dir, rng.uniform(-0.6, 0.6)) * length * rng.uniform(0.25, 0.45);
    spec.control[2] = spec.control[3] - end_dir * length * rng.uniform(0.25, 0.45);
  }
  spec.max_width = width;
  spec.root_ratio = rng.uniform(0.5, 1.0);
  spec.peak_at = rng.uniform(0.1, 0.4);
  spec.tip_ratio = rng.chance(0.7) ? 0.0 : rng.uniform(0.25, 0.5);
  spec.max_width *= head.strand_scale;
  if (kind != StrandKind::kBang && kind != StrandKind::kUnderCap && rng.chance(0.35)) {
    // Wavy locks; amplitude kept below the strand's curvature limit.
    spec.wave_amplitude = r * rng.uniform(0.04, kind == StrandKind::kTail ? 0.12 : 0.09);
    spec.wave_cycles = rng.uniform(1.2, 2.8);
    spec.wave_phase = rng.uniform(0.0, 2.0 * kPi);
  }

  StrandGeometry g = sample_strand(spec);
  s.outline = strand_outline(g);
  s.colour = vary(pal.hair, rng);
  s.tone = rng.chance(0.3) ? 0.0 : rng.uniform(0.12, 0.45);
  s.reverse_param = rng.chance(0.3);
  if (options.shading == Shading::kTwoTone) {
    s.band = band_polygon(g, rng.chance(0.5) ? 1 : -1, rng.uniform(0.0, 0.2),
                          rng.uniform(0.6, 0.95), rng.uniform(0.25, 0.45));
  }
  // Forks only where both halves stay wide enough to be regions of their own.
  if (spec.max_width >= 7.0 * options.line_width && rng.chance(0.2)) {
    s.inner_lines.push_back(fork_line(g, rng.chance(0.5) ? 1 : -1, rng.uniform(0.4, 0.65)));
    if (options.fading_forks) {
      // The drawn part runs from the tip over 45–85% of the line; the rest,
      // where it would bend out to the side, is only in the annotation.
      Polyline& drawn = s.inner_lines.back();
      const double keep = rng.uniform(0.45, 0.85) * polyline_length(drawn);
      double along = 0.0;
      std::size_t cut = 1;
      while (cut + 1 < drawn.size() && along + (drawn[cut] - drawn[cut - 1]).norm() < keep) {
        along += (drawn[cut] - drawn[cut - 1]).norm();
        ++cut;
      }
      s.hidden_lines.emplace_back(drawn.begin() + static_cast<std::ptrdiff_t>(cut - 1),
                                  drawn.end());
      drawn.resize(cut);
    }
  }
  s.geometry = std::move(g);
  return s;
}

}  // namespace hair25d::generator
