// Back hair joined across the neck and body (case 1 of §5.1 at region
// level): the back hair is one mass hanging behind the head, and the neck
// and the body lie in front of it, so pieces seen on both sides of the neck
// share no occluder that is hair, and their outlines run along the neck,
// not the face (session 13).
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "bank_crossings.h"
#include "face_joins.h"
#include "join_paint.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// Rays each way, as the mass joins (kMinMassRays).
constexpr int kMinBodyRays = 3;
// A ray goes on through this many pixels in a row that are neither the body
// nor hair lying over the pieces (the drawn lines between a piece, the neck
// and the face).
constexpr double kMaxLineRun = 6.0;
// A ray crosses at least this many pixels of the neck or body, not the face:
// pieces facing each other across the face alone are the face joins' (they
// need runs along it; on generated seeds 101-116 and 201-216 every
// candidate crossing the face only whose paint matched was two strands lying
// on the face, as screentone 110's bangs 17 and 25).
constexpr double kMinNeckRun = 4.0;
// Pieces lying on the body: when more than this share of each piece's rays
// have the body again behind the piece's far side, both lie in front of it
// (strands hanging over the neck), not behind. Right candidates of 101-116
// and 201-216 measured at most 0.50 on one of the two sides.
constexpr double kMaxFarBodyShare = 0.75;
// Ink, not body: luma under this share of Options::dark_luma.
constexpr double kInkShare = 0.5;

struct BodyRay {
  int index = 0;  // along the outline
  Vec2 from{0, 0}, to{0, 0};
  bool far_body = false;     // the body lies behind the piece's far side too
  std::vector<int> crossed;  // hair regions crossed
};

}  // namespace

cv::Mat body_mask(const Context& ctx, const Face& face, bool dark_body) {
  if (face.pixels == 0) return {};
  const int w = ctx.labels.width(), h = ctx.labels.height();
  const Options& o = *ctx.options;
  // Open pixels as the face's (`open_pixels`), but with `dark_body` the neck
  // and body may be painted darker than `dark_luma` (the generator's clothes
  // have HSV value 0.3-0.9, so about half of them lie below it, and the neck
  // between two back pieces was no body: two-tone 106): only ink, under
  // kInkShare x dark_luma, parts the areas then. The drawn lines' cores (the
  // generator's value 0.03-0.12) are darker still.
  const int ink = dark_body ? static_cast<int>(kInkShare * o.dark_luma) : o.dark_luma;
  cv::Mat open(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgba& c = ctx.image->at(x, y);
      if (ctx.labels.at(x, y) == 0 && c.a > 0 && luma(c) >= ink) open.at<std::uint8_t>(y, x) = 1;
    }
  cv::Mat components;
  const int count = cv::connectedComponents(open, components, 4, CV_32S);
  // The paper: the open area with most pixels on the image's border (the
  // body reaches the bottom edge only).
  std::vector<int> border(count, 0);
  for (int x = 0; x < w; ++x)
    ++border[components.at<int>(0, x)], ++border[components.at<int>(h - 1, x)];
  for (int y = 0; y < h; ++y)
    ++border[components.at<int>(y, 0)], ++border[components.at<int>(y, w - 1)];
  int paper = 0;
  for (int c = 1; c < count; ++c)
    if (border[c] > 0 && (paper == 0 || border[c] > border[paper])) paper = c;
  // The face's neighbours across its drawn line: the neck, the body.
  cv::Mat near;
  const int r = 2 * o.outline_reach + 3;
  cv::dilate(face.mask, near, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}));
  std::vector<char> keep(count, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int c = components.at<int>(y, x);
      if (c != 0 && c != paper && near.at<std::uint8_t>(y, x)) keep[c] = 1;
    }
  cv::Mat mask = face.mask.clone();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (keep[components.at<int>(y, x)]) mask.at<std::uint8_t>(y, x) = 1;
  return mask;
}

std::vector<MassJoin> body_join_candidates(const Context& ctx, const Face& drawn_face,
                                           const std::set<int>& front, RegionTones& tones,
                                           RegionFields& fields, cv::Mat* body_out) {
  std::vector<MassJoin> out;
  if (drawn_face.pixels == 0) return out;
  TailedHair tailed = tailed_hair(ctx, ctx.front());
  untail_back_paint(ctx, ctx.front(), fields.cels(), &tailed);
  std::set<int> pieces;
  for (const auto& [id, info] : ctx.regions)
    if (!front.count(id) && !tailed.tails.count(id)) pieces.insert(id);
  if (pieces.size() < 2) return out;
  const cv::Mat near_face = ctx.options->face_piece_mass_step > 0 && tones.screentone()
                                ? near_face_mask(drawn_face.mask)
                                : cv::Mat();
  cv::Mat& body = *body_out;
  // Dark clothes count on cel drawings, whose paint test is exact
  // (`RegionCels`): on gradient 201-216 two wrong joins crossed dark
  // clothes with windows under 10 RGB apart (208: two bangs lying on the
  // face; 216: a strand lying on the clothes, and the back).
  body = body_mask(ctx, drawn_face, !tones.screentone() && fields.cels().cel_drawing());
  const cv::Mat& face = drawn_face.mask;
  cv::Rect hair;
  for (const auto& [id, info] : ctx.regions) hair = hair.area() == 0 ? info.box : (hair | info.box);
  const double reach = 0.5 * std::max(hair.width, hair.height);
  const auto on = [](const cv::Mat& mask, const Vec2& p) {
    const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
    return x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask.at<std::uint8_t>(y, x) != 0;
  };
  // rays[a][b]: rays from a's outline, along its outward normal, across the
  // body (and hair lying over a), landing on b.
  std::map<int, std::map<int, std::vector<BodyRay>>> rays;
  for (int id : pieces) {
    const auto& c = ctx.regions.at(id).contour;
    const int n = static_cast<int>(c.size());
    if (n < 8) continue;
    for (int i = 0; i < n; i += 2) {
      const auto leaving = outward_ray(ctx, c, i, id);
      if (!leaving) continue;
      const auto& [p, normal] = *leaving;
      BodyRay ray;
      double line = 0.0, neck = 0.0;
      for (double s = 1.0; s <= reach; s += 0.7) {
        const Vec2 x = p + s * normal;
        const int l = ctx.label(x);
        if (l == id && s < 3.0) continue;
        if (l == id) break;
        if (l == 0) {
          if (on(body, x)) {
            line = 0.0;
            if (!on(face, x)) neck += 0.7;
          } else if ((line += 0.7) > kMaxLineRun) {
            break;
          }
          continue;
        }
        line = 0.0;
        if (pieces.count(l)) {
          if (neck < kMinNeckRun) break;
          ray.index = i, ray.from = p, ray.to = x;
          // Behind the start, across the piece: does the body show again?
          double depth = 0.0;
          while (depth < 200.0 && ctx.label(p - (depth + 1.0) * normal) == id) depth += 1.0;
          for (double u = depth + 1.0; u <= depth + 1.0 + kMaxLineRun; u += 0.7) {
            const Vec2 y = p - u * normal;
            if (on(body, y)) {
              ray.far_body = true;
              break;
            }
            if (ctx.label(y) != 0) break;
          }
          rays[id][l].push_back(std::move(ray));
          break;
        }
        // Hair lying over the piece hides the back hair as the body does.
        if (!ctx.is_above(l, id)) break;
        if (ray.crossed.empty() || ray.crossed.back() != l) ray.crossed.push_back(l);
      }
    }
  }
  for (const auto& [a, targets] : rays)
    for (const auto& [b, ab] : targets) {
      if (b <= a) continue;
      auto back = rays.find(b);
      if (back == rays.end() || !back->second.count(a)) continue;
      if (ctx.is_above(a, b) || ctx.is_above(b, a)) continue;
      // Hair crossed lies over one of the two pieces.
      const auto kept = [&](const std::vector<BodyRay>& list, int from, int to) {
        std::vector<BodyRay> k;
        for (const BodyRay& r : list) {
          bool ok = true;
          for (int l : r.crossed) ok = ok && (ctx.is_above(l, from) || ctx.is_above(l, to));
          if (ok) k.push_back(r);
        }
        return k;
      };
      const std::vector<BodyRay> kab = kept(ab, a, b), kba = kept(back->second.at(a), b, a);
      const int fewer = static_cast<int>(std::min(kab.size(), kba.size()));
      if (fewer < kMinBodyRays) continue;
      const auto far = [](const std::vector<BodyRay>& list) {
        int n = 0;
        for (const BodyRay& r : list) n += r.far_body;
        return static_cast<double>(n) / list.size();
      };
      if (far(kab) > kMaxFarBodyShare && far(kba) > kMaxFarBodyShare) continue;
      // Paint: the tone's dots on screentone (both measured and one tone),
      // the flat colours on a cel drawing, else one linear field painting
      // both pieces. The windows at the rays' ends are no test across the
      // neck (session 16): the gap is wide, and on gradient drawings
      // 2000-2099 they passed 5 body candidates (steps 2.5-7.4 RGB), all
      // two strands (under and back, tails, a bang), while the 2 right ones
      // of 3000-3099 (2.1, 3.1) had their pieces already joined.
      bool paint = false;
      double step = 0.0;
      if (tones.screentone()) {
        paint = tones.match(a, b) == RegionTones::Match::kSame &&
                !strand_on_face(ctx, tones, near_face, a, b);
      } else if (fields.cels().cel_drawing()) {
        const RegionCels::Judgement cel = fields.cels().judge(a, b);
        paint = cel.same || cel.step <= kMaxMassCelStep;
        step = cel.step;
      } else {
        const auto median_step = [&](const std::vector<BodyRay>& list, int from, int to) {
          std::vector<double> steps;
          for (const BodyRay& r : list) {
            const Vec2 d = (r.to - r.from).normalized();
            steps.push_back(
                (colour_near(ctx, from, r.from, -d) - colour_near(ctx, to, r.to, d)).norm());
          }
          std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
          return steps[steps.size() / 2];
        };
        step = std::max(median_step(kab, a, b), median_step(kba, b, a));
        paint = fields.step(a, b) <= kMaxMassFieldStep;
      }
      if (!paint) continue;
      out.push_back(mass_join(a, b, fewer, step, kab));
    }
  sort_by_rays(out);
  return out;
}

}  // namespace hair25d::completion::detail
