#include "face_joins.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "join_curves.h"

namespace hair25d::completion::detail {
namespace {

// A run of a region's outline along the face (at least this long, pixels).
constexpr int kMinRunLength = 12;
// Pieces on opposite sides: the directions from their runs to the face's
// centre differ by at least this angle.
constexpr double kMinOppositeAngle = M_PI / 3;
// Share of the straight line between two runs that must lie over the face
// or regions above the pieces (they face each other across the face).
constexpr double kMinCover = 0.85;
// The face must hold at least this share of the hair's pixels: a few paper
// pixels between strands next to the head centre are no face.
constexpr double kMinFaceShare = 0.02;

// Least mean depth of a back-hair piece behind its run, in face radii.
constexpr double kMinDepth = 0.3;
// RGB distance from the skin around the head centre of a piece of skin cut
// off by strands lying on the face.
constexpr double kMaxSkinDistance = 30.0;
// A run bulging into the face by more than this share of its chord is a
// tip lying on the face.
constexpr double kMinSagitta = 0.04;

double luma(const Rgba& c) { return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b; }

struct FaceRun {
  int region = 0;
  int begin = 0, end = 0;  // contour indices (unwrapped)
  Polyline points;
  Eigen::Vector3d colour{0, 0, 0};
};

}  // namespace

cv::Mat open_pixels(const Context& ctx) {
  const int w = ctx.labels.width(), h = ctx.labels.height();
  const Options& o = *ctx.options;
  cv::Mat open(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgba& c = ctx.image->at(x, y);
      if (ctx.labels.at(x, y) == 0 && c.a > 0 && luma(c) >= o.dark_luma)
        open.at<std::uint8_t>(y, x) = 1;
    }
  return open;
}

Face find_face(const Context& ctx) {
  Face face;
  const int w = ctx.labels.width(), h = ctx.labels.height();
  cv::Rect hair;
  int hair_pixels = 0;
  for (const auto& [id, info] : ctx.regions) {
    hair = hair.area() == 0 ? info.box : (hair | info.box);
    hair_pixels += info.pixels;
  }
  if (hair.area() == 0) return face;
  // The face lies within the hair's reach of the head: beyond it an open
  // line lets the area run into the neck, the body or the paper.
  const double radius = 0.5 * std::max(hair.width, hair.height);
  const Options& o = *ctx.options;
  const cv::Mat open = open_pixels(ctx);
  // Seed: the open pixel nearest the head centre, within a third of the reach.
  const int hx = static_cast<int>(std::floor(ctx.head.x()));
  const int hy = static_cast<int>(std::floor(ctx.head.y()));
  const int seek = static_cast<int>(radius / 3);
  cv::Point seed(-1, -1);
  long best = -1;
  for (int y = std::max(0, hy - seek); y <= std::min(h - 1, hy + seek); ++y)
    for (int x = std::max(0, hx - seek); x <= std::min(w - 1, hx + seek); ++x) {
      if (!open.at<std::uint8_t>(y, x)) continue;
      const long d = static_cast<long>(x - hx) * (x - hx) + static_cast<long>(y - hy) * (y - hy);
      if (best < 0 || d < best) best = d, seed = {x, y};
    }
  if (best < 0 || best > static_cast<long>(seek) * seek) return face;
  cv::Mat components;
  const int count = cv::connectedComponents(open, components, 4, CV_32S);
  // Per component: mean colour, pixels, pixels beyond the reach, touches the
  // image border.
  struct Part {
    Eigen::Vector3d sum{0, 0, 0};
    int pixels = 0, outside = 0;
    bool border = false;
  };
  std::vector<Part> parts(count);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int c = components.at<int>(y, x);
      if (c == 0) continue;
      Part& part = parts[c];
      const Rgba& px = ctx.image->at(x, y);
      part.sum += Eigen::Vector3d(px.r, px.g, px.b);
      ++part.pixels;
      const double dx = x + 0.5 - ctx.head.x(), dy = y + 0.5 - ctx.head.y();
      if (dx * dx + dy * dy > radius * radius) ++part.outside;
      if (x == 0 || y == 0 || x == w - 1 || y == h - 1) part.border = true;
    }
  // Strands lying across the face cut it into pieces: the other pieces of
  // the skin's colour within the reach belong to it (pieces of paper reach
  // the image border or have another colour).
  const int seed_id = components.at<int>(seed);
  const Eigen::Vector3d skin = parts[seed_id].sum / parts[seed_id].pixels;
  std::vector<char> keep(count, 0);
  keep[seed_id] = 1;
  for (int c = 1; c < count; ++c) {
    const Part& part = parts[c];
    if (part.border || part.outside * 2 > part.pixels) continue;
    if ((part.sum / part.pixels - skin).norm() <= kMaxSkinDistance) keep[c] = 1;
  }
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  cv::Mat hair_or_face(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (keep[components.at<int>(y, x)] && components.at<int>(y, x) != 0)
        mask.at<std::uint8_t>(y, x) = 1;
      if (mask.at<std::uint8_t>(y, x) || ctx.labels.at(x, y) != 0)
        hair_or_face.at<std::uint8_t>(y, x) = 1;
    }
  // Eyes, mouth and lines on the face are face too: the dark pixels that
  // the face and the hair enclose together (strands lying on the face stay
  // out: they are occluders in their own right).
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(hair_or_face.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  cv::Mat enclosed(h, w, CV_8U, cv::Scalar(0));
  cv::drawContours(enclosed, contours, -1, cv::Scalar(1), cv::FILLED);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (enclosed.at<std::uint8_t>(y, x) && !hair_or_face.at<std::uint8_t>(y, x) &&
          luma(ctx.image->at(x, y)) < o.dark_luma)
        mask.at<std::uint8_t>(y, x) = 1;
  // ... and its drawn outline, up to the hair's outline reach.
  cv::Mat grown;
  const int r = o.outline_reach;
  cv::dilate(mask, grown, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}));
  double sx = 0, sy = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t& m = grown.at<std::uint8_t>(y, x);
      const double dx = x + 0.5 - ctx.head.x(), dy = y + 0.5 - ctx.head.y();
      if (ctx.labels.at(x, y) != 0 || dx * dx + dy * dy > radius * radius) m = 0;
      if (m) ++face.pixels, sx += x + 0.5, sy += y + 0.5;
    }
  if (face.pixels < kMinFaceShare * hair_pixels) {
    face.pixels = 0;
    return face;
  }
  face.mask = grown;
  face.centroid = Vec2(sx / face.pixels, sy / face.pixels);
  return face;
}

std::vector<FaceJoin> face_join_candidates(const Context& ctx, const Face& face,
                                           const std::set<int>& front) {
  std::vector<FaceJoin> out;
  if (face.pixels == 0) return out;
  const Options& o = *ctx.options;
  cv::Mat near;
  const int k = o.occluder_reach + 1;
  cv::dilate(face.mask, near, cv::getStructuringElement(cv::MORPH_RECT, {2 * k + 1, 2 * k + 1}));
  auto on_face = [&](const Vec2& p) {
    const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
    return x >= 0 && y >= 0 && x < face.mask.cols && y < face.mask.rows &&
           face.mask.at<std::uint8_t>(y, x) != 0;
  };

  std::vector<FaceRun> runs;
  const double face_radius = std::sqrt(face.pixels / M_PI);
  for (const auto& [id, info] : ctx.regions) {
    if (front.count(id)) continue;
    const auto& c = info.contour;
    const int n = static_cast<int>(c.size());
    if (n < kMinRunLength) continue;
    // The piece's cut edge runs along the face and along the hair above it
    // (strands lying on the face's edge, the cap): both hide it.
    std::vector<char> along(n), by_face(n);
    const int reach = o.occluder_reach;
    for (int i = 0; i < n; ++i) {
      by_face[i] = near.at<std::uint8_t>(c[i]) != 0;
      bool hidden = by_face[i];
      for (int dy = -reach; dy <= reach && !hidden; ++dy)
        for (int dx = -reach; dx <= reach && !hidden; ++dx) {
          const int l = ctx.label(c[i].x + dx, c[i].y + dy);
          hidden = l != 0 && l != id && ctx.is_above(l, id);
        }
      along[i] = hidden;
    }
    // Runs along the face alone and along the face with the hair above:
    // the longer run may wander onto a strand's side, the shorter may be
    // too little of the face's curve; either may show the cut.
    const int gap = static_cast<int>(std::ceil(o.merge_gap));
    std::vector<std::pair<int, int>> spans;  // unwrapped [begin, end]
    for (const std::vector<char>* mark : {&by_face, &along}) {
      int start = -1;  // a visible point, so runs do not wrap
      for (int i = 0; i < n && start < 0; ++i)
        if (!(*mark)[i]) start = i;
      if (start < 0) continue;  // an island: nothing faces it
      const std::size_t first = spans.size();
      for (int s = 1; s <= n; ++s) {
        const int i = start + s;
        if (!(*mark)[i % n]) continue;
        if (spans.size() > first && i - spans.back().second - 1 <= gap)
          spans.back().second = i;
        else
          spans.push_back({i, i});
      }
    }
    for (const auto& [b, e] : spans) {
      int face_points = 0;
      for (int i = b; i <= e; ++i) face_points += by_face[i % n];
      if (face_points < kMinRunLength) continue;
      FaceRun run;
      run.region = id;
      run.begin = b, run.end = e;
      for (int i = b; i <= e; ++i) run.points.emplace_back(c[i % n].x + 0.5, c[i % n].y + 0.5);
      // The face hides the piece: along the run the piece lies on the side
      // away from the face's centre and the face (or hair above the piece)
      // on the other, and the run does not bulge into the face (a strand's
      // tip lying on the face does).
      const Vec2 p = run.points.front(), q = run.points.back();
      Vec2 mean = Vec2::Zero();
      for (const Vec2& x : run.points) mean += x;
      mean /= static_cast<double>(run.points.size());
      const Vec2 bulge = mean - 0.5 * (p + q);
      Vec2 d = mean - face.centroid;
      if (d.norm() < 1.0) continue;
      d.normalize();
      if (bulge.dot(d) < -kMinSagitta * (q - p).norm()) continue;
      int outer = 0, inner = 0, samples = 0;
      for (std::size_t i = 0; i < run.points.size(); i += 3) {
        const Vec2& x = run.points[i];
        ++samples;
        outer += ctx.label(x + 4.0 * d) == id;
        const Vec2 below = x - (k + 3.0) * d;
        const int under = ctx.label(below);
        inner += on_face(below) || (under != 0 && under != id && ctx.is_above(under, id));
      }
      if (2 * outer < samples || 2 * inner < samples) continue;
      // Back hair is wide behind its cut; a strand lying along the face's
      // edge is thin.
      double depth = 0.0;
      for (std::size_t i = 0; i < run.points.size(); i += 3) {
        double t = 1.0;
        while (t < 2 * face_radius && ctx.label(run.points[i] + t * d) == id) t += 1.0;
        depth += t;
      }
      depth /= samples;
      if (depth < kMinDepth * face_radius) continue;
      Eigen::Vector3d sum(0, 0, 0);
      int count = 0;
      for (std::size_t i = 0; i < run.points.size(); i += 2)
        for (int dy = -5; dy <= 5; ++dy)
          for (int dx = -5; dx <= 5; ++dx) {
            const int x = static_cast<int>(run.points[i].x()) + dx;
            const int y = static_cast<int>(run.points[i].y()) + dy;
            if (!ctx.original->contains(x, y) || ctx.original->at(x, y) != id) continue;
            const Rgba& px = ctx.image->at(x, y);
            sum += Eigen::Vector3d(px.r, px.g, px.b);
            ++count;
          }
      run.colour = count > 0 ? Eigen::Vector3d(sum / count) : info.colour;
      runs.push_back(std::move(run));
    }
  }

  for (std::size_t i = 0; i < runs.size(); ++i)
    for (std::size_t j = i + 1; j < runs.size(); ++j) {
      const FaceRun& a = runs[i];
      const FaceRun& b = runs[j];
      if (a.region == b.region) continue;
      if (ctx.is_above(a.region, b.region) || ctx.is_above(b.region, a.region)) continue;
      const double colour = (a.colour - b.colour).norm();
      if (colour > o.max_colour_distance) continue;
      const Vec2 ma = a.points[a.points.size() / 2], mb = b.points[b.points.size() / 2];
      const Vec2 da = face.centroid - ma, db = face.centroid - mb;
      if (da.norm() < 1 || db.norm() < 1) continue;
      const double opposite =
          std::acos(std::clamp(da.dot(db) / (da.norm() * db.norm()), -1.0, 1.0));
      if (opposite < kMinOppositeAngle) continue;
      // The straight line between them crosses the face or hair above them.
      const double length = (mb - ma).norm();
      int total = 0, covered = 0;
      for (double s = 0; s <= length; s += 1.0) {
        const Vec2 x = ma + (s / std::max(length, 1.0)) * (mb - ma);
        const int l = ctx.label(x);
        if (l == a.region || l == b.region) continue;
        ++total;
        if (on_face(x) || (l != 0 && (ctx.is_above(l, a.region) || ctx.is_above(l, b.region))))
          ++covered;
      }
      const double cover = total > 0 ? static_cast<double>(covered) / total : 1.0;
      if (cover < kMinCover) continue;
      FaceJoin join;
      join.region_a = a.region;
      join.region_b = b.region;
      join.pa = a.points.front(), join.qa = a.points.back();
      join.pb = b.points.front(), join.qb = b.points.back();
      join.cost = 0.5 + 0.4 * colour / o.max_colour_distance + 3.0 * (1.0 - cover) +
                  (M_PI - opposite) / M_PI;
      if (join.cost > o.max_join_cost) continue;
      join.begin_a = a.begin, join.end_a = a.end;
      join.begin_b = b.begin, join.end_b = b.end;
      join.patch = face_join_patch(ctx, join);
      out.push_back(std::move(join));
    }
  std::sort(out.begin(), out.end(),
            [](const FaceJoin& x, const FaceJoin& y) { return x.cost < y.cost; });
  return out;
}

}  // namespace hair25d::completion::detail
