#include "hair25d/segment/graph_cut.h"

#include <maxflow.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <set>
#include <sstream>

#include "colour_model.h"
#include "hair25d/core/error.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/regions.h"
#include "mesh_topology.h"
#include "paper.h"

namespace hair25d::segment {

bool GraphCutOptions::is_valid(std::string* error) const {
  std::ostringstream o;
  const std::string p = "segment::GraphCutOptions::";
  if (!(phi_curve >= 0.0 && std::isfinite(phi_curve)))
    o << p << "phi_curve = " << phi_curve << "; must be >= 0";
  else if (!(phi_other >= 0.0 && std::isfinite(phi_other)))
    o << p << "phi_other = " << phi_other << "; must be >= 0";
  else if (!(unary_weight > 0.0 && std::isfinite(unary_weight)))
    o << p << "unary_weight = " << unary_weight << "; must be > 0";
  else if (!(min_probability > 0.0 && min_probability < 1.0))
    o << p << "min_probability = " << min_probability << "; must be in (0, 1)";
  else if (!(distance_sigma_fraction > 0.0 && std::isfinite(distance_sigma_fraction)))
    o << p << "distance_sigma_fraction = " << distance_sigma_fraction << "; must be > 0";
  else if (gmm_components < 1 || gmm_components > 8)
    o << p << "gmm_components = " << gmm_components << "; must be in [1, 8]";
  else if (!(colour_sigma_min >= 1.0 && colour_sigma_min <= 255.0))
    o << p << "colour_sigma_min = " << colour_sigma_min << "; must be in [1, 255]";
  else if (!(hair_colour_share >= 0.0 && hair_colour_share <= 1.0))
    o << p << "hair_colour_share = " << hair_colour_share << "; must be in [0, 1]";
  else if (max_undrawn_run < 0)
    o << p << "max_undrawn_run = " << max_undrawn_run << "; must be >= 0";
  else if (max_cycles < 1)
    o << p << "max_cycles = " << max_cycles << "; must be >= 1";
  if (o.str().empty()) return true;
  if (error) *error = o.str();
  return false;
}

namespace {

using Graph = maxflow::Graph_DDD;
constexpr double kHard = 1e12;  // cost of leaving a triangle under a stroke

struct Problem {
  int nf = 0;
  int nl = 0;                  // labels: index 0 = background, then hair labels
  std::vector<int> label_ids;  // stroke label of each index
  std::vector<double> unary;   // nf × nl
  std::vector<int> seed;       // per triangle: label index or -1
  std::vector<std::array<int, 3>> nb;
  std::vector<std::array<double, 3>> w;  // pairwise weight across each edge
  double u(int t, int l) const { return unary[static_cast<std::size_t>(t) * nl + l]; }
};

// Energy of one component's labelling (pairwise counted once per edge).
double energy(const Problem& pr, const std::vector<int>& tris, const std::vector<int>& lab) {
  double e = 0.0;
  for (int t : tris) {
    e += pr.seed[t] >= 0 && pr.seed[t] != lab[t] ? kHard : pr.u(t, lab[t]);
    for (int k = 0; k < 3; ++k) {
      const int o = pr.nb[t][k];
      if (o > t && lab[o] != lab[t]) e += pr.w[t][k];
    }
  }
  return e;
}

// α-expansion (Boykov, Veksler, Zabih) over the candidate labels of one component.
int expand(const Problem& pr, const std::vector<int>& tris, const std::vector<int>& candidates,
           int max_cycles, std::vector<int>& lab, std::vector<int>& local, bool* converged) {
  const int n = static_cast<int>(tris.size());
  for (int i = 0; i < n; ++i) local[tris[i]] = i;
  double current = energy(pr, tris, lab);
  int cycle = 0;
  *converged = false;
  while (cycle < max_cycles) {
    ++cycle;
    bool improved = false;
    for (int alpha : candidates) {
      Graph g(n, n * 3 / 2 + 1);
      g.add_node(n);
      std::vector<double> cost0(n), cost1(n);  // keep, switch to alpha
      for (int i = 0; i < n; ++i) {
        const int t = tris[i];
        auto d = [&](int l) { return pr.seed[t] >= 0 && pr.seed[t] != l ? kHard : pr.u(t, l); };
        cost0[i] = d(lab[t]);
        cost1[i] = d(alpha);
      }
      for (int i = 0; i < n; ++i) {
        const int t = tris[i];
        for (int k = 0; k < 3; ++k) {
          const int o = pr.nb[t][k];
          if (o <= t || local[o] < 0 || pr.w[t][k] <= 0.0) continue;
          const int j = local[o];
          const double wt = pr.w[t][k];
          const double A = lab[t] != lab[o] ? wt : 0.0;  // both keep
          const double B = lab[t] != alpha ? wt : 0.0;   // i keeps, j switches
          const double C = alpha != lab[o] ? wt : 0.0;   // i switches, j keeps
          // D = 0: both alpha. Split into unary parts and one submodular edge.
          cost1[i] += C - A;
          cost1[j] += 0.0 - C;
          const double cap = B + C - A;
          if (cap > 0.0) g.add_edge(i, j, cap, 0.0);
          // The constant A is left out: energies are compared afresh below.
        }
      }
      for (int i = 0; i < n; ++i) {
        const double m = std::min(cost0[i], cost1[i]);
        g.add_tweights(i, cost1[i] - m, cost0[i] - m);
      }
      g.maxflow();
      std::vector<int> proposal = lab;
      bool changed = false;
      for (int i = 0; i < n; ++i) {
        if (g.what_segment(i) == Graph::SINK && lab[tris[i]] != alpha) {
          proposal[tris[i]] = alpha;
          changed = true;
        }
      }
      if (!changed) continue;
      const double e = energy(pr, tris, proposal);
      if (e < current - 1e-9 * std::max(1.0, std::abs(current))) {
        for (int t : tris) lab[t] = proposal[t];
        current = e;
        improved = true;
      }
    }
    if (!improved) {
      *converged = true;
      break;
    }
  }
  for (int t : tris) local[t] = -1;
  return cycle;
}

}  // namespace

GraphCutResult graph_cut_labels(const Image& image, const TriMesh2& mesh, const Strokes& strokes,
                                const LabelMap& line_mask, const GraphCutOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  if (image.empty()) throw Error("segment::graph_cut_labels: the image is empty");
  mesh.validate("segment::graph_cut_labels mesh");
  const int W = image.width(), H = image.height();
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (mesh.V(v, 0) < -0.5 || mesh.V(v, 1) < -0.5 || mesh.V(v, 0) > W + 0.5 ||
        mesh.V(v, 1) > H + 0.5) {
      std::ostringstream o;
      o << "segment::graph_cut_labels: mesh vertex " << v << " at (" << mesh.V(v, 0) << ", "
        << mesh.V(v, 1) << ") lies outside the " << W << "x" << H << " image";
      throw Error(o.str());
    }
  }
  const bool use_mask = !line_mask.empty();
  if (use_mask && (line_mask.width() != W || line_mask.height() != H))
    throw Error("segment::graph_cut_labels: line mask is " + std::to_string(line_mask.width()) +
                "x" + std::to_string(line_mask.height()) + "; must match the " + std::to_string(W) +
                "x" + std::to_string(H) + " image");

  // A stroke over transparent paper marks nothing: paper is no hair, and its
  // colour is no sample of any label.
  LabelMap painted = rasterize_strokes(strokes, W, H);
  std::set<int> present;
  bool has_background_strokes = false;
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      int& s = painted.at(x, y);
      if (s == kNoStroke) continue;
      if (detail::is_paper(image.at(x, y))) {
        s = kNoStroke;
        continue;
      }
      if (s > 0) present.insert(s);
      if (s == 0) has_background_strokes = true;
    }
  }
  if (present.empty())
    throw Error(
        "segment::graph_cut_labels: the strokes hold no hair stroke (label > 0) on an "
        "opaque pixel (alpha >= " +
        std::to_string(kOpaqueAlpha) + ") of the " + std::to_string(W) + "x" + std::to_string(H) +
        " image; mark at least one hair region");

  Problem pr;
  pr.nf = mesh.triangle_count();
  pr.label_ids.push_back(0);
  pr.label_ids.insert(pr.label_ids.end(), present.begin(), present.end());
  pr.nl = static_cast<int>(pr.label_ids.size());
  std::map<int, int> index_of;
  for (int i = 0; i < pr.nl; ++i) index_of[pr.label_ids[i]] = i;

  // Triangle colours and stroke votes from the pixels each triangle holds.
  const LabelMap tri = rasterize_triangles(mesh, W, H);
  std::vector<Eigen::Vector3d> colour_sum(pr.nf, Eigen::Vector3d::Zero()), all_sum = colour_sum;
  std::vector<int> colour_n(pr.nf, 0), all_n(pr.nf, 0);
  std::vector<Eigen::Vector3d> paper_sum(pr.nf, Eigen::Vector3d::Zero());
  std::vector<int> paper_n(pr.nf, 0);
  std::vector<std::vector<Eigen::Vector3d>> samples(pr.nl), line_samples(pr.nl);
  std::vector<std::map<int, int>> votes(pr.nf), line_votes(pr.nf);
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const int t = tri.at(x, y);
      if (t < 0) continue;
      const Rgba& p = image.at(x, y);
      // Transparent paper is seen as white (as the line detector sees it);
      // it enters a triangle's colour only if nothing opaque does.
      const Eigen::Vector3d c = detail::colour_on_white(p);
      const bool paper = detail::is_paper(p);
      const bool on_line = use_mask && line_mask.at(x, y) != 0;
      if (paper) {
        paper_sum[t] += c;
        ++paper_n[t];
        continue;
      }
      all_sum[t] += c;
      ++all_n[t];
      if (!on_line) colour_sum[t] += c, ++colour_n[t];
      const int s = painted.at(x, y);
      if (s == kNoStroke) continue;
      const int li = index_of.at(s);
      (on_line ? line_samples : samples)[li].push_back(c);
      ++(on_line ? line_votes : votes)[t][li];
    }
  }
  // A stroke drawn only on line pixels still counts.
  for (int l = 0; l < pr.nl; ++l) {
    if (!samples[l].empty()) continue;
    samples[l] = line_samples[l];
    for (int t = 0; t < pr.nf; ++t)
      if (auto it = line_votes[t].find(l); it != line_votes[t].end()) votes[t][l] += it->second;
  }
  pr.seed.assign(pr.nf, -1);
  for (int t = 0; t < pr.nf; ++t) {
    int best = 0;
    for (const auto& [l, n] : votes[t])
      if (n > best) best = n, pr.seed[t] = l;
  }

  // One model per label and one for all hair; each fit is independent, so
  // they are spread over the cores (index nl is the hair model).
  std::vector<detail::ColourModel> models(pr.nl + 1);
  std::vector<Eigen::Vector3d> hair_samples;
  for (int l = 1; l < pr.nl; ++l)
    hair_samples.insert(hair_samples.end(), samples[l].begin(), samples[l].end());
  cv::parallel_for_(cv::Range(0, pr.nl + 1), [&](const cv::Range& range) {
    for (int l = range.start; l < range.end; ++l)
      models[l] = detail::ColourModel::fit(l < pr.nl ? samples[l] : hair_samples,
                                           options.gmm_components, options.colour_sigma_min);
  });
  const detail::ColourModel hair_model = std::move(models.back());
  models.pop_back();

  // Distance to each label's strokes on a coarse grid: the term is smooth over
  // hundreds of pixels, so a few pixels of error do not matter.
  const int f = std::max(1, static_cast<int>(std::ceil(std::max(W, H) / 128.0)));
  const int gw = (W + f - 1) / f, gh = (H + f - 1) / f;
  std::vector<cv::Mat> dist(pr.nl), free(pr.nl);
  std::vector<char> any(pr.nl, 0);
  for (int l = 0; l < pr.nl; ++l) free[l] = cv::Mat(gh, gw, CV_8U, cv::Scalar(1));
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const int s = painted.at(x, y);
      if (s == kNoStroke) continue;
      const int l = index_of.at(s);
      free[l].at<std::uint8_t>(y / f, x / f) = 0;
      any[l] = 1;
    }
  }
  cv::parallel_for_(cv::Range(0, pr.nl), [&](const cv::Range& range) {
    for (int l = range.start; l < range.end; ++l)
      if (any[l]) cv::distanceTransform(free[l], dist[l], cv::DIST_L2, 3, CV_32F);
  });
  const double sigma_d = options.distance_sigma_fraction * std::sqrt(double(W) * H);

  pr.unary.assign(static_cast<std::size_t>(pr.nf) * pr.nl, 0.0);
  const double log_min = -std::log(options.min_probability);
  // Each triangle's terms are its own: the triangles are spread over the cores.
  cv::parallel_for_(cv::Range(0, pr.nf), [&](const cv::Range& range) {
    for (int t = range.start; t < range.end; ++t) {
      const Eigen::Vector2d a = mesh.V.row(mesh.F(t, 0)), b = mesh.V.row(mesh.F(t, 1)),
                            c = mesh.V.row(mesh.F(t, 2));
      const double area = 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
      const Eigen::Vector2d centroid = (a + b + c) / 3.0;
      Eigen::Vector3d colour;
      if (colour_n[t] > 0) {
        colour = colour_sum[t] / colour_n[t];
      } else if (all_n[t] > 0) {
        colour = all_sum[t] / all_n[t];
      } else if (paper_n[t] > 0) {
        colour = paper_sum[t] / paper_n[t];
      } else {
        const int x = std::clamp(static_cast<int>(centroid.x()), 0, W - 1);
        const int y = std::clamp(static_cast<int>(centroid.y()), 0, H - 1);
        colour = detail::colour_on_white(image.at(x, y));
      }
      const int gx = std::clamp(static_cast<int>(centroid.x()) / f, 0, gw - 1);
      const int gy = std::clamp(static_cast<int>(centroid.y()) / f, 0, gh - 1);
      auto proximity = [&](int l) {
        if (dist[l].empty()) return 0.0;
        const double d = dist[l].at<float>(gy, gx) * f;
        return std::exp(-0.5 * d * d / (sigma_d * sigma_d));
      };
      const double hair_sim = options.hair_colour_share * hair_model.similarity(colour);
      double pf = 0.0;
      std::vector<double> p(pr.nl, 0.0);
      for (int l = 1; l < pr.nl; ++l) {
        p[l] = std::max(models[l].similarity(colour), hair_sim) * proximity(l);
        pf = std::max(pf, p[l]);
      }
      p[0] = 1.0 - pf;
      if (has_background_strokes && !models[0].empty())
        p[0] = std::max(p[0], models[0].similarity(colour) * proximity(0));
      // A triangle mostly on transparent paper is background: paper is no hair.
      bool on_paper = 2 * paper_n[t] > paper_n[t] + all_n[t];
      if (paper_n[t] + all_n[t] == 0) {
        const int x = std::clamp(static_cast<int>(centroid.x()), 0, W - 1);
        const int y = std::clamp(static_cast<int>(centroid.y()), 0, H - 1);
        on_paper = detail::is_paper(image.at(x, y));
      }
      for (int l = 0; l < pr.nl; ++l) {
        const double cost = std::min(log_min, -std::log(std::max(p[l], 1e-300)));
        pr.unary[static_cast<std::size_t>(t) * pr.nl + l] =
            l > 0 && on_paper ? kHard : options.unary_weight * area * cost;
      }
    }
  });

  // A curve edge is free to cut only where a line is drawn: the links that
  // close gaps between lines are guesses, and cutting them costs as much as
  // cutting anywhere else (the pieces either side are solved together).
  auto drawn = [&](int t, int k) {
    if (!use_mask) return true;
    const Eigen::Vector2d a = mesh.V.row(mesh.F(t, k)), b = mesh.V.row(mesh.F(t, (k + 1) % 3));
    const int n = std::max(1, static_cast<int>(std::ceil(2.0 * (b - a).norm())));
    int run = 0, longest = 0;
    for (int i = 0; i <= n; ++i) {
      const Eigen::Vector2d p = a + (b - a) * (double(i) / n);
      const int x = std::clamp(static_cast<int>(p.x()), 0, W - 1);
      const int y = std::clamp(static_cast<int>(p.y()), 0, H - 1);
      run = line_mask.at(x, y) ? 0 : run + 1;
      longest = std::max(longest, run);
    }
    return longest <= options.max_undrawn_run * 2;  // samples are half a pixel apart
  };
  pr.nb = detail::triangle_neighbours(mesh);
  pr.w.assign(pr.nf, {0.0, 0.0, 0.0});
  detail::UnionFind uf(pr.nf);
  for (int t = 0; t < pr.nf; ++t) {
    for (int k = 0; k < 3; ++k) {
      if (pr.nb[t][k] < 0) continue;
      const double len = (mesh.V.row(mesh.F(t, k)) - mesh.V.row(mesh.F(t, (k + 1) % 3))).norm();
      const double phi =
          detail::edge_on_curve(mesh, t, k) && drawn(t, k) ? options.phi_curve : options.phi_other;
      pr.w[t][k] = phi * len;
      if (pr.w[t][k] > 0.0) uf.unite(t, pr.nb[t][k]);
    }
  }

  // Curve edges cost nothing to cut, so the energy splits into independent
  // pieces: each is solved alone over the few labels that can win there.
  std::map<int, std::vector<int>> pieces;
  for (int t = 0; t < pr.nf; ++t) pieces[uf.find(t)].push_back(t);
  GraphCutResult result;
  result.components = static_cast<int>(pieces.size());
  std::vector<int> lab(pr.nf, 0), local(pr.nf, -1);
  std::vector<double> total(pr.nl);
  for (const auto& [root, tris] : pieces) {
    // A hair label enters a piece through its strokes; a piece without any
    // can only be background or the one hair label that fits it best.
    std::set<int> cand{0};
    for (int t : tris)
      if (pr.seed[t] >= 0) cand.insert(pr.seed[t]);
    if (cand.size() == 1 && !options.unmarked_faces_background) {
      std::fill(total.begin(), total.end(), 0.0);
      for (int t : tris)
        for (int l = 1; l < pr.nl; ++l) total[l] += pr.u(t, l);
      cand.insert(
          static_cast<int>(std::min_element(total.begin() + 1, total.end()) - total.begin()));
    }
    const std::vector<int> candidates(cand.begin(), cand.end());
    for (int t : tris) {
      if (pr.seed[t] >= 0) {
        lab[t] = pr.seed[t];
        continue;
      }
      int best = candidates[0];
      for (int l : candidates)
        if (pr.u(t, l) < pr.u(t, best)) best = l;
      lab[t] = best;
    }
    if (candidates.size() > 1 && tris.size() > 1) {
      bool converged = true;
      const int cycles = expand(pr, tris, candidates, options.max_cycles, lab, local, &converged);
      result.cycles = std::max(result.cycles, cycles);
      result.converged = result.converged && converged;
    }
    result.energy += energy(pr, tris, lab);
  }
  result.labels.resize(pr.nf);
  for (int t = 0; t < pr.nf; ++t) result.labels[t] = pr.label_ids[lab[t]];
  return result;
}

}  // namespace hair25d::segment
