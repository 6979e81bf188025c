#include "eval_joins_overlay.h"

#include <cstdio>
#include <map>
#include <opencv2/imgproc.hpp>
#include <set>

#include "hair25d/core/image_io.h"

namespace hair25d::completion::test {

void write_join_overlay(const std::filesystem::path& path, const AnnotatedCase& c, const Result& r,
                        const std::string& name) {
  const int w = c.image.width(), h = c.image.height();
  cv::Mat out(h, w, CV_8UC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgba& p = c.image.at(x, y);
      out.at<cv::Vec3b>(y, x) = cv::Vec3b(128 + p.b / 2, 128 + p.g / 2, 128 + p.r / 2);
      // Each region tinted its own colour, to tell slivers apart.
      if (const int l = c.regions.at(x, y); l != 0) {
        const unsigned hash = static_cast<unsigned>(l) * 2654435761u;
        const cv::Vec3b tint(hash >> 24, (hash >> 16) & 255, (hash >> 8) & 255);
        cv::Vec3b& o = out.at<cv::Vec3b>(y, x);
        for (int k = 0; k < 3; ++k) o[k] = static_cast<uchar>((o[k] + tint[k]) / 2);
      }
    }
  std::map<int, cv::Point2d> centre;
  std::map<int, int> count;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (const int l = c.regions.at(x, y); l != 0) {
        centre[l] += cv::Point2d(x, y);
        ++count[l];
      }
  for (auto& [l, p] : centre) p /= count[l];
  std::map<int, int> truth, predicted;
  for (const AnnotatedRegion& reg : c.region_list) truth[reg.id] = reg.strand;
  for (std::size_t s = 0; s < r.strands.size(); ++s)
    for (int id : r.strands[s].regions) predicted[id] = static_cast<int>(s);
  // The annotation's strands: each region to the nearest earlier one of its strand.
  std::map<int, std::vector<int>> members;
  for (const auto& [id, s] : truth)
    if (centre.count(id)) members[s].push_back(id);
  for (const auto& [s, ids] : members) {
    if (ids.size() < 2) continue;
    std::map<int, std::vector<int>> parts;
    for (int id : ids) parts[predicted.count(id) ? predicted[id] : -id].push_back(id);
    if (parts.size() < 2) continue;
    std::printf("%s: strand %d in %zu parts:", name.c_str(), s, parts.size());
    for (const auto& [p, list] : parts) {
      std::printf(" {");
      for (int id : list) std::printf(" %d", id);
      std::printf(" }");
    }
    std::printf("\n");
  }
  for (const auto& [s, ids] : members)
    for (std::size_t i = 1; i < ids.size(); ++i) {
      int best = ids[0];
      for (std::size_t j = 0; j < i; ++j)
        if (cv::norm(centre[ids[j]] - centre[ids[i]]) < cv::norm(centre[best] - centre[ids[i]]))
          best = ids[j];
      const bool got = predicted[best] == predicted[ids[i]];
      cv::line(out, centre[best], centre[ids[i]],
               got ? cv::Scalar(0, 160, 160) : cv::Scalar(0, 230, 255), got ? 1 : 3, cv::LINE_AA);
      if (!got) std::printf("%s: missed %d-%d\n", name.c_str(), best, ids[i]);
    }
  // Predicted strands that hold regions of several annotated strands: the
  // wrong pairs, whichever join made them (edge joins, path, face or seam
  // joins, equal relations), not only the edge joins drawn below.
  std::map<int, std::map<int, std::vector<int>>> by_predicted;
  for (const auto& [id, s] : predicted)
    if (truth.count(id)) by_predicted[s][truth[id]].push_back(id);
  for (const auto& [s, parts] : by_predicted) {
    if (parts.size() < 2) continue;
    std::printf("%s: merged strands", name.c_str());
    for (const auto& [t, list] : parts) {
      std::printf(" %d{", t);
      for (int id : list) std::printf(" %d", id);
      std::printf(" }");
    }
    std::printf("\n");
  }
  for (const EdgeReport& e : r.edges) {
    if (e.completion != EdgeCase::kJoined || e.joined_region < e.region) continue;
    const bool right = truth[e.region] == truth[e.joined_region];
    // From this edge's middle to the partner region's joined edge.
    cv::Point2d a((e.p.x() + e.q.x()) / 2, (e.p.y() + e.q.y()) / 2), b = centre[e.joined_region];
    for (const EdgeReport& f : r.edges)
      if (f.region == e.joined_region && f.joined_region == e.region)
        b = cv::Point2d((f.p.x() + f.q.x()) / 2, (f.p.y() + f.q.y()) / 2);
    cv::line(out, a, b, right ? cv::Scalar(0, 170, 0) : cv::Scalar(0, 0, 255), 2, cv::LINE_AA);
    cv::circle(out, a, 3, cv::Scalar(255, 0, 0), -1);
    if (!right) std::printf("%s: wrong %d-%d\n", name.c_str(), e.region, e.joined_region);
  }
  // Cropped to the hair and doubled, so that slivers and their ids can be read.
  cv::Rect box;
  for (const auto& [l, p] : centre) box |= cv::Rect(cv::Point(p), cv::Size(1, 1));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (c.regions.at(x, y) != 0) box |= cv::Rect(x, y, 1, 1);
  box = cv::Rect(box.x - 10, box.y - 10, box.width + 20, box.height + 20) & cv::Rect(0, 0, w, h);
  cv::Mat zoom;
  cv::resize(out(box), zoom, cv::Size(), 2.0, 2.0, cv::INTER_LINEAR);
  for (const auto& [l, p] : centre)
    cv::putText(zoom, std::to_string(l), (p - cv::Point2d(box.tl())) * 2.0,
                cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 0, 0), 2);
  Image img(zoom.cols, zoom.rows);
  for (int y = 0; y < zoom.rows; ++y)
    for (int x = 0; x < zoom.cols; ++x) {
      const cv::Vec3b v = zoom.at<cv::Vec3b>(y, x);
      img.at(x, y) = Rgba{v[2], v[1], v[0], 255};
    }
  save_image(path, img);
}

}  // namespace hair25d::completion::test
