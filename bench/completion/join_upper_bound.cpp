#include "join_upper_bound.h"

#include <cmath>
#include <map>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <set>

#include "hair25d/completion/completion.h"

namespace hair25d::completion::test {
namespace {

struct Groups {
  std::map<int, int> parent;
  int find(int x) {
    while (parent.at(x) != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
  int pairs() {
    std::map<int, int> size;
    for (const auto& [id, p] : parent) ++size[find(id)];
    int n = 0;
    for (const auto& [root, s] : size) n += s * (s - 1) / 2;
    return n;
  }
};

// Pieces `members` linked through pixels whose label is in `pass` (plus
// label 0 within 3 px of an occluder pixel, or inside `extra`) are united.
void link(const LabelMap& labels, const std::vector<int>& members, const std::set<int>& pass,
          const cv::Mat& extra, Groups* groups) {
  const int w = labels.width(), h = labels.height();
  cv::Mat occ(h, w, CV_8U, cv::Scalar(0)), open(h, w, CV_8U, cv::Scalar(0));
  const std::set<int> mine(members.begin(), members.end());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int l = labels.at(x, y);
      if (pass.count(l)) occ.at<std::uint8_t>(y, x) = 255;
      if (pass.count(l) || mine.count(l)) open.at<std::uint8_t>(y, x) = 255;
    }
  cv::Mat near;
  cv::dilate(occ, near, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(7, 7)));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (labels.at(x, y) == 0 &&
          (near.at<std::uint8_t>(y, x) || (!extra.empty() && extra.at<std::uint8_t>(y, x))))
        open.at<std::uint8_t>(y, x) = 255;
  cv::Mat comp;
  cv::connectedComponents(open, comp, 8, CV_32S);
  std::map<int, int> first;  // component -> a piece in it
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int l = labels.at(x, y);
      if (!mine.count(l)) continue;
      const int k = comp.at<int>(y, x);
      auto [it, fresh] = first.emplace(k, l);
      if (!fresh) groups->unite(it->second, l);
    }
}

}  // namespace

UpperBound join_upper_bound(const AnnotatedCase& c, std::FILE* csv,
                            const std::map<int, int>* joined) {
  const Options o;
  const LabelMap labels = assign_outline_pixels(c.image, c.regions, o.outline_reach, o.dark_luma);
  std::map<int, std::set<int>> direct, above;  // region -> regions above it
  for (const AnnotatedPair& p : c.pairs) {
    if (p.relation == Relation::kAbove) direct[p.b].insert(p.a);
    if (p.relation == Relation::kBelow) direct[p.a].insert(p.b);
  }
  std::set<std::pair<int, int>> equal;  // touching halves of one strand
  for (const AnnotatedPair& p : c.pairs)
    if (p.relation == Relation::kEqual) equal.insert({std::min(p.a, p.b), std::max(p.a, p.b)});
  std::map<int, std::vector<int>> strands;
  for (const AnnotatedRegion& r : c.region_list) strands[r.strand].push_back(r.id);
  for (const AnnotatedRegion& r : c.region_list) {
    std::vector<int> stack(direct[r.id].begin(), direct[r.id].end());
    std::set<int>& seen = above[r.id];
    while (!stack.empty()) {
      const int x = stack.back();
      stack.pop_back();
      if (!seen.insert(x).second) continue;
      stack.insert(stack.end(), direct[x].begin(), direct[x].end());
    }
  }
  UpperBound ub;
  std::map<int, int> strand_of;
  for (const AnnotatedRegion& r : c.region_list) strand_of[r.id] = r.strand;
  const auto linked_under_both = [&](int a, int b) {
    if (equal.count({std::min(a, b), std::max(a, b)})) return true;
    std::set<int> common;
    for (int u : above[a])
      if (above[b].count(u)) common.insert(u);
    if (common.empty()) return false;
    Groups one;
    one.parent[a] = a;
    one.parent[b] = b;
    link(labels, {a, b}, common, cv::Mat(), &one);
    return one.find(a) == one.find(b);
  };
  std::set<int> front;
  for (const auto& [id, ups] : above) front.insert(ups.begin(), ups.end());
  std::map<int, std::string> name_of;
  for (const AnnotatedRegion& r : c.region_list) name_of[r.id] = r.name;
  std::map<int, cv::Vec3d> mean, spread;
  std::map<int, int> count;
  for (int y = 0; y < c.regions.height(); ++y)
    for (int x = 0; x < c.regions.width(); ++x) {
      const int l = c.regions.at(x, y);
      if (!l) continue;
      const Rgba& px = c.image.at(x, y);
      cv::Vec3d v(px.r, px.g, px.b);
      mean[l] += v;
      spread[l] += v.mul(v);
      ++count[l];
    }
  for (auto& [l, m] : mean) {
    m /= count[l];
    const cv::Vec3d sq = spread[l] / count[l] - m.mul(m);
    spread[l] = cv::Vec3d(std::sqrt(std::max(0.0, sq[0])), std::sqrt(std::max(0.0, sq[1])),
                          std::sqrt(std::max(0.0, sq[2])));
  }
  for (const auto& [a, sa] : strand_of)
    for (const auto& [b, sb] : strand_of) {
      if (b <= a || above[a].count(b) || above[b].count(a)) continue;
      const bool both = linked_under_both(a, b);
      if (sa != sb) {
        ++ub.other_pairs;
        ub.other_linked += both;
      }
      if (!csv) continue;
      std::set<int> either(above[a].begin(), above[a].end());
      either.insert(above[b].begin(), above[b].end());
      Groups one;
      one.parent[a] = a;
      one.parent[b] = b;
      link(labels, {a, b}, either, cv::Mat(), &one);
      const bool j =
          joined && joined->count(a) && joined->count(b) && joined->at(a) == joined->at(b);
      std::fprintf(csv, "%s,%d,%d,%s,%s,%d,%d,%d,%d,%d,%.1f,%.1f,%.1f,%d,%d,%d\n", c.name.c_str(),
                   a, b, name_of[a].c_str(), name_of[b].c_str(), sa == sb, !front.count(a),
                   !front.count(b), both, one.find(a) == one.find(b), cv::norm(mean[a] - mean[b]),
                   cv::norm(spread[a]), cv::norm(spread[b]), count[a], count[b], j);
    }
  for (const auto& [strand, members] : strands) {
    const int n = static_cast<int>(members.size());
    ub.truth += n * (n - 1) / 2;
    if (n < 2) continue;
    Groups both, chained, whole, face;
    for (int m : members) both.parent[m] = chained.parent[m] = whole.parent[m] = face.parent[m] = m;
    std::set<int> any;
    for (int m : members) any.insert(above[m].begin(), above[m].end());
    for (int m : members) any.erase(m);  // a strand cannot lie above itself
    const cv::Mat none;
    link(labels, members, any, none, &whole);
    cv::Mat mask;
    if (auto it = c.strand_masks.find(strand); it != c.strand_masks.end()) {
      mask = cv::Mat(labels.height(), labels.width(), CV_8U, cv::Scalar(0));
      for (int y = 0; y < labels.height(); ++y)
        for (int x = 0; x < labels.width(); ++x)
          if (it->second.at(x, y)) mask.at<std::uint8_t>(y, x) = 255;
    }
    link(labels, members, any, mask, &face);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        if (linked_under_both(members[i], members[j])) {
          ++ub.both_direct;
          chained.unite(members[i], members[j]);
        }
      }
    ub.both_chained += chained.pairs();
    ub.strand_chained += whole.pairs();
    ub.strand_face_chained += face.pairs();
  }
  return ub;
}

}  // namespace hair25d::completion::test
