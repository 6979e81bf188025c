#include "front_outlines.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// Pixels less opaque than this are the sheet, never a shape on the hair.
constexpr int kOpaque = 128;
// How far (px) from the hair a shape's colour may lie across its outline:
// wikipe-tan's clips are edged by two lines 3-4 px wide with a light band
// between them (up to 9.5 px from the hair).
constexpr int kAcross = 12;
// Contour steps either side of a junction over which a line's turn is read.
constexpr int kArm = 10;
// A border shorter than this (contour steps) is a touch, not a shared line.
constexpr int kMinRun = 12;
// Contour steps past each end of the border whose outline is kept too: the
// hair's outline growth crept on along the shape's line from the junction.
constexpr int kExtend = 12;
// At a junction the shape's outline runs on within kSmooth degrees and the
// hair's turns by kMargin more (wikipe-tan's clip over her twin tail: 21
// against 99, 27 against 122), or the other way round where the hair lies
// on top. Where no third area is seen, or where the hair changes region
// along the border, the shape's outline bends sharply by kSharp or more.
constexpr double kSmooth = 40.0;
constexpr double kMargin = 30.0;
constexpr double kSharp = 60.0;
// Where the hair along the border changes from one region to another, one
// whose outline runs on within kStraight degrees and kMargin straighter than
// the shape's lies over the shape (a lock over a generated face whose chin
// lies over the back hair: 22 against 99; the crown beside wikipe-tan's
// clip turns by 22, the clip by 39).
constexpr double kStraight = 25.0;
// On the head, the most (degrees) the face's border with a region may bend
// and still be the face's outline lying over it (generated chins over the
// back hair: 9-21; where locks' points dent it: 42-123).
constexpr double kFaceBend = 30.0;

// The turn (degrees) of the path a -> b -> c at b; 180 where two points coincide.
double turn_deg(const cv::Point& a, const cv::Point& b, const cv::Point& c) {
  return angle(Vec2(b.x - a.x, b.y - a.y), Vec2(c.x - b.x, c.y - b.y)) * 180.0 / M_PI;
}

// The hair regions (outlines assigned) over the working box, and for every
// pixel within kAcross the region nearest to it and how far.
struct HairNear {
  cv::Mat labels;   // CV_32S, the regions
  cv::Mat nearest;  // CV_32S: the nearest region within kAcross, or 0
  cv::Mat dist;     // CV_8U: chessboard distance to the hair, 255 beyond kAcross
};

HairNear hair_near(const cv::Mat& labels) {
  HairNear hn;
  hn.labels = labels;
  // Chessboard distance to the hair (DIST_C is exact with a 3x3 mask) and
  // the hair pixel it is measured to, whose region is the nearest one.
  const cv::Mat off_hair = labels == 0;
  cv::Mat dist, index;
  cv::distanceTransform(off_hair, dist, index, cv::DIST_C, 3, cv::DIST_LABEL_PIXEL);
  std::vector<int> region_of_index(1, 0);
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x)
      if (labels.at<int>(y, x) != 0) {
        const int k = index.at<int>(y, x);
        if (k >= static_cast<int>(region_of_index.size())) region_of_index.resize(k + 1, 0);
        region_of_index[k] = labels.at<int>(y, x);
      }
  hn.nearest = cv::Mat(labels.size(), CV_32S, cv::Scalar(0));
  hn.dist = cv::Mat(labels.size(), CV_8U, cv::Scalar(255));
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x) {
      const float d = dist.at<float>(y, x);
      if (d > kAcross) continue;
      hn.nearest.at<int>(y, x) = region_of_index[index.at<int>(y, x)];
      hn.dist.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(d);
    }
  return hn;
}

// Region `id`'s outline (all the hair's for −1) at the junction nearest `p`:
// its turn from the side along the shape (towards `inner`) to the side away
// from it, and a point on that side; turn −1 when none of it lies near.
struct HairEnd {
  double turn = -1.0;
  cv::Point at, away;
};

HairEnd hair_end(const HairNear& hn, int id, const cv::Point& p, const cv::Point& inner) {
  HairEnd end;
  // Traced in a window round p: the arms reach kArm steps from a point
  // within kAcross + 2 of it.
  constexpr int kWindow = kAcross + 2 * kArm + 4;
  const cv::Rect window = cv::Rect(p.x - kWindow, p.y - kWindow, 2 * kWindow + 1, 2 * kWindow + 1) &
                          cv::Rect(0, 0, hn.labels.cols, hn.labels.rows);
  const cv::Mat part = hn.labels(window);
  std::vector<std::vector<cv::Point>> lines;
  cv::findContours(id < 0 ? part != 0 : part == id, lines, cv::RETR_LIST, cv::CHAIN_APPROX_NONE,
                   window.tl());
  const std::vector<cv::Point>* best = nullptr;
  int k = 0;
  double best_d = kAcross + 2;
  for (const auto& line : lines)
    for (std::size_t i = 0; i < line.size(); ++i) {
      const double d = std::hypot(line[i].x - p.x, line[i].y - p.y);
      if (d <= best_d) best_d = d, best = &line, k = static_cast<int>(i);
    }
  if (best == nullptr) return end;
  const auto& q = *best;
  const int n = static_cast<int>(q.size());
  if (n < 2 * kArm + 1) return end;
  const cv::Point a = q[static_cast<std::size_t>(wrap(k - kArm, n))];
  const cv::Point b = q[static_cast<std::size_t>(wrap(k + kArm, n))];
  end.at = q[static_cast<std::size_t>(k)];
  const bool a_along =
      std::hypot(a.x - inner.x, a.y - inner.y) <= std::hypot(b.x - inner.x, b.y - inner.y);
  end.away = a_along ? b : a;
  end.turn = a_along ? turn_deg(a, end.at, b) : turn_deg(b, end.at, a);
  return end;
}

}  // namespace

cv::Mat front_outlines(const Image& image, const LabelMap& drawn, const LabelMap& labels,
                       const cv::Mat& dark, const cv::Mat& head, const cv::Mat& face) {
  const int w = image.width(), h = image.height();
  cv::Mat keep(h, w, CV_8U, cv::Scalar(0));
  const cv::Rect hair_box = cv::boundingRect(view(labels) != 0);
  if (hair_box.empty()) return keep;
  const int margin = kAcross + kArm + kExtend + 4;
  const cv::Rect box = cv::Rect(hair_box.x - margin, hair_box.y - margin,
                                hair_box.width + 2 * margin, hair_box.height + 2 * margin) &
                       cv::Rect(0, 0, w, h);
  const HairNear hn = hair_near(view(labels)(box));

  const cv::Mat regions = view(drawn)(box);
  // Light: opaque, not dark, no region.
  cv::Mat alpha, light;
  cv::extractChannel(view(image)(box), alpha, 3);
  light = (alpha >= kOpaque) & (dark(box) == 0) & (hn.labels == 0);
  // The shapes: light areas a 5x5 square fits into (a clip's light edge
  // band between its two lines is thinner and part of its outline).
  cv::Mat thick, parts;
  cv::morphologyEx(light, thick, cv::MORPH_OPEN,
                   cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
  cv::Mat stats, centres;
  cv::connectedComponentsWithStats(thick, parts, stats, centres, 8, CV_32S);
  // The sheet round the figure lies behind everything: the areas reaching
  // past the hair's top and one side, and the pieces of their colour the
  // hair cuts off from them.
  const int components = stats.rows;
  std::vector<std::uint8_t> sheet(static_cast<std::size_t>(components), 0);
  {
    std::vector<cv::Vec3d> mean(static_cast<std::size_t>(components), cv::Vec3d(0, 0, 0));
    for (int y = 0; y < box.height; ++y)
      for (int x = 0; x < box.width; ++x) {
        const int k = parts.at<int>(y, x);
        if (k == 0) continue;
        const Rgba& c = image.at(box.x + x, box.y + y);
        mean[static_cast<std::size_t>(k)] += cv::Vec3d(c.r, c.g, c.b);
      }
    std::vector<cv::Vec3d> colours;
    for (int k = 1; k < components; ++k) {
      mean[static_cast<std::size_t>(k)] /= stats.at<int>(k, cv::CC_STAT_AREA);
      const int left = stats.at<int>(k, cv::CC_STAT_LEFT);
      const int right = left + stats.at<int>(k, cv::CC_STAT_WIDTH);
      if (stats.at<int>(k, cv::CC_STAT_TOP) == 0 && (left == 0 || right == box.width))
        colours.push_back(mean[static_cast<std::size_t>(k)]);
    }
    constexpr double kSheetColour = 12.0;
    for (int k = 1; k < components; ++k)
      for (const cv::Vec3d& c : colours)
        if (cv::norm(mean[static_cast<std::size_t>(k)] - c) <= kSheetColour)
          sheet[static_cast<std::size_t>(k)] = 1;
  }
  std::vector<std::vector<cv::Point>> shapes;
  cv::findContours(thick.clone(), shapes, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);
  cv::Mat kept(box.size(), CV_8U, cv::Scalar(0));

  // A junction is three areas meeting: between the shape's outline running
  // on and the hair's turning away lies a third one (the paper, another
  // shape, the clear sheet). Where the border ends on a dark feature (an eye
  // under the bangs) none does. Two hair regions meeting on the shape's
  // border tell nothing: their separating line ends there whether the shape
  // lies over them or they both lie over it.
  auto third_area = [&](const cv::Point& p, const cv::Point& on, const HairEnd& hair, int own) {
    const double ux = on.x - p.x, uy = on.y - p.y, vx = hair.away.x - hair.at.x,
                 vy = hair.away.y - hair.at.y;
    const double nu = std::hypot(ux, uy), nv = std::hypot(vx, vy);
    if (nu == 0 || nv == 0) return false;
    double bx = ux / nu + vx / nv, by = uy / nu + vy / nv;
    const double nb = std::hypot(bx, by);
    if (nb < 1e-6) return false;
    bx /= nb, by /= nb;
    const double ox = 0.5 * (p.x + hair.at.x), oy = 0.5 * (p.y + hair.at.y);
    for (double t = 2.0; t <= kAcross; t += 1.0) {
      const int x = static_cast<int>(std::floor(ox + 0.5 + t * bx));
      const int y = static_cast<int>(std::floor(oy + 0.5 + t * by));
      if (x < 0 || y < 0 || x >= box.width || y >= box.height || hn.labels.at<int>(y, x) != 0)
        return false;
      const int c = parts.at<int>(y, x);
      if ((c != 0 && c != own) || image.at(box.x + x, box.y + y).a < kOpaque) return true;
    }
    return false;
  };
  // Walks from contour points i0..i1 across the line between the shape and
  // the hair, along the normal, up to `reach` px, keeping what they cross.
  auto walk = [&](const std::vector<cv::Point>& shape, int i0, int i1, double reach) {
    const int n = static_cast<int>(shape.size());
    auto pt = [&](int i) { return shape[static_cast<std::size_t>(wrap(i, n))]; };
    const cv::Rect all(0, 0, box.width, box.height);
    for (int i = i0; i <= i1; ++i) {
      const cv::Point p = pt(i), a = pt(i - 2), b = pt(i + 2);
      double nx = b.y - a.y, ny = -(b.x - a.x);
      const double norm = std::hypot(nx, ny);
      if (norm == 0) continue;
      nx /= norm, ny /= norm;
      auto cell = [&](double t) {
        return cv::Point(static_cast<int>(std::floor(p.x + 0.5 + t * nx)),
                         static_cast<int>(std::floor(p.y + 0.5 + t * ny)));
      };
      const cv::Point probe = cell(2.0);
      if (probe.inside(all) && thick.at<std::uint8_t>(probe)) nx = -nx, ny = -ny;
      for (double t = 0.5; t <= reach; t += 0.5) {
        const cv::Point c = cell(t);
        if (!c.inside(all)) break;
        if (t <= 1.5 && thick.at<std::uint8_t>(c)) continue;  // still the shape's rim
        if (regions.at<int>(c) != 0 || thick.at<std::uint8_t>(c) ||
            image.at(box.x + c.x, box.y + c.y).a < kOpaque)
          break;
        kept.at<std::uint8_t>(c) = 255;
      }
    }
  };

  struct Run {
    int s, e;
    float gap;
    int on_top, below;  // ends voting so
  };
  for (const auto& shape : shapes) {
    const int n = static_cast<int>(shape.size());
    if (n < 2 * kArm + kMinRun) continue;
    std::vector<float> d(static_cast<std::size_t>(n));
    int count = 0;
    for (int i = 0; i < n; ++i) {
      d[static_cast<std::size_t>(i)] = hn.dist.at<std::uint8_t>(shape[static_cast<std::size_t>(i)]);
      count += d[static_cast<std::size_t>(i)] <= kAcross;
    }
    // Wholly on the hair (a clip enclosed by it) or away from it: no
    // junction to read.
    if (count == 0 || count == n) continue;
    auto dist_at = [&](int i) { return d[static_cast<std::size_t>(wrap(i, n))]; };
    auto faces = [&](int i) { return dist_at(i) <= kAcross; };
    auto pt = [&](int i) { return shape[static_cast<std::size_t>(wrap(i, n))]; };
    auto region_at = [&](int i) { return hn.nearest.at<int>(pt(i)); };
    const int own = parts.at<int>(shape[0]);
    if (sheet[static_cast<std::size_t>(own)]) continue;
    // The face: locks lying over it dent its border with their points and
    // cross its chin, and what its border with them says was as often wrong
    // as right on generated drawings; the head's own rules are left alone.
    {
      int on_face = 0;
      for (const cv::Point& p : shape) {
        const int x = p.x + box.x, y = p.y + box.y;
        on_face += (!face.empty() && face.at<std::uint8_t>(y, x)) ||
                   (!head.empty() && head.at<std::uint8_t>(y, x));
      }
      if (2 * on_face >= n) continue;
    }
    int start = 0;
    while (!(faces(start) && !faces(start - 1))) ++start;
    std::vector<Run> runs;
    for (int s = start; s < start + n;) {
      if (!(faces(s) && !faces(s - 1))) {
        ++s;
        continue;
      }
      int e = s;
      while (e + 1 < s + n && faces(e + 1)) ++e;
      if (e - s + 1 < kMinRun) {
        s = e + 1;
        continue;
      }
      // The junctions: the border's points nearest its ends still at its
      // usual distance from the hair (the facing test runs on a few px past
      // the junction where the hair leaves at a slant).
      std::vector<float> ds;
      for (int i = s; i <= e; ++i) ds.push_back(dist_at(i));
      std::nth_element(ds.begin(), ds.begin() + ds.size() / 2, ds.end());
      const float gap = ds[ds.size() / 2];
      int js = s, je = e;
      while (js < e && dist_at(js) > gap + 2) ++js;
      while (je > js && dist_at(je) > gap + 2) --je;
      Run run{s, e, gap, 0, 0};
      for (const auto& [j, step] : {std::pair{js, -1}, std::pair{je, 1}}) {
        const double ta = turn_deg(pt(j - kArm), pt(j), pt(j + kArm));
        const HairEnd hair = hair_end(hn, -1, pt(j), pt(j - step * kArm));
        if (hair.turn < 0) continue;
        const bool junction = third_area(pt(j), pt(j + step * kArm), hair, own);
        // Without a third area seen, only a sharp turn of the shape against
        // the hair's running on counts (a shirt's top line ending on a lock
        // over it: 109-135 against 4-11; the hair running on hidden into a
        // clip's notch: 41 against 1).
        if (junction) run.on_top += ta <= kSmooth && hair.turn >= ta + kMargin;
        run.below += hair.turn <= kSmooth && ta >= hair.turn + (junction ? kMargin : kSharp);
      }
      runs.push_back(run);
      s = e + 1;
    }
    // A shape over the hair shows it at most of its borders' ends. Where the
    // hair runs on hidden under the shape (into a notch of it) the border
    // ends without a junction, and the shape's outline turns there as if the
    // hair lay on top: such a run counts when the rest of the shape says so.
    int on_top = 0, below = 0;
    for (const Run& r : runs) on_top += r.on_top, below += r.below;
    const bool shape_on_top = on_top >= 2 && on_top >= 3 * below;
    for (const Run& r : runs) {
      // On the head the bangs lie on the face, whose borders with them end
      // on eyes and locks' points: one end says too little there.
      const cv::Point mid = pt((r.s + r.e) / 2);
      const bool on_head = !head.empty() && head.at<std::uint8_t>(mid.y + box.y, mid.x + box.x);
      const bool keep_run =
          r.on_top == 2 || (r.on_top == 1 && r.below == 0 && shape_on_top && !on_head);
      if (!keep_run) continue;
      // Along the border the hair may change from one region to another
      // lying over the shape (a lock hanging over a face whose chin lies
      // over the back hair): where the shape's outline turns and that
      // region's runs on, the stretch facing it is that region's outline.
      std::vector<std::pair<int, int>> parts_of_run;  // [first, last] facing one region
      for (int i = r.s; i <= r.e;) {
        int k = i;
        while (k + 1 <= r.e && region_at(k + 1) == region_at(i)) ++k;
        parts_of_run.emplace_back(i, k);
        i = k + 1;
      }
      std::vector<std::uint8_t> under(parts_of_run.size(), 0);
      int dents = 0;
      for (std::size_t k = 0; k + 1 < parts_of_run.size(); ++k) {
        const int j = parts_of_run[k].second;
        const double ta = turn_deg(pt(j - kArm), pt(j), pt(j + kArm));
        dents += ta >= kSharp;
        const int before = region_at(j), after = region_at(j + 1);
        const HairEnd x = hair_end(hn, before, pt(j), pt(j - kArm));
        const HairEnd y = hair_end(hn, after, pt(j + 1), pt(j + 1 + kArm));
        if (x.turn >= 0 && x.turn <= kStraight && ta >= x.turn + kMargin) under[k] = 1;
        if (y.turn >= 0 && y.turn <= kStraight && ta >= y.turn + kMargin) under[k + 1] = 1;
      }
      // A shape lying on the hair keeps its own smooth outline along it;
      // one whose border bends sharply where the hair changes from one
      // region to another is dented by locks lying on it (generated faces
      // under their fringes: 2-4 such bends; wikipe-tan's clip: none).
      if (dents >= 2) continue;
      // A region found over the shape at one of its changes lies over it all
      // along (a lock's tip poking into the face shows both its sides).
      std::vector<int> over;
      for (std::size_t k = 0; k < parts_of_run.size(); ++k)
        if (under[k]) over.push_back(region_at(parts_of_run[k].first));
      for (std::size_t k = 0; k < parts_of_run.size(); ++k) {
        const auto [first, last] = parts_of_run[k];
        if (std::find(over.begin(), over.end(), region_at(first)) != over.end()) continue;
        // On the head the face's outline lies over the back hair as a smooth
        // curve; where its border with the hair bends, locks lie on the face
        // and dent it with their points.
        const cv::Point middle = pt((first + last) / 2);
        if (!head.empty() && head.at<std::uint8_t>(middle.y + box.y, middle.x + box.x)) {
          double most = 0;
          for (int i = first; i <= last; ++i)
            most = std::max(most, turn_deg(pt(i - kArm), pt(i), pt(i + kArm)));
          if (most > kFaceBend) continue;
        }
        const int i0 = k == 0 ? r.s - kExtend : parts_of_run[k].first;
        const int i1 = k + 1 == parts_of_run.size() ? r.e + kExtend : parts_of_run[k].second;
        walk(shape, i0, i1, std::sqrt(2.0) * r.gap + 2.0);  // the gap is chessboard
      }
    }
  }
  // The walks from neighbouring contour points leave gaps on a convex side.
  cv::dilate(kept, kept, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3)));
  kept &= (regions == 0) & (thick == 0);
  kept.copyTo(keep(box));
  return keep;
}

}  // namespace hair25d::completion::detail
