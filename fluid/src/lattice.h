// Private interface between the public Solver and the lattice, which is templated on the
// scalar type (float or double) and chosen at run time.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "hair25d/fluid/options.h"
#include "hair25d/fluid/solver.h"
#include "worker_pool.h"

namespace hair25d::fluid {

// One lattice link cut by a filament, seen from the fluid cell that receives the bounced
// population: the population arriving at `cell` along direction `dir` comes back from the wall.
struct CutLink {
  std::int32_t cell = 0;       // y * width + x
  std::uint8_t dir = 0;        // D2Q9 direction of the incoming population (1..8)
  float ux = 0.0f, uy = 0.0f;  // wall velocity at the crossing
  std::int32_t owner = 0;      // global segment id
};

// Finds the links cut by the filaments. Keeps per-cell scratch so a call costs O(links) and
// no sort over all of them: hair skeletons move, so this runs every step.
class LinkCutter {
 public:
  LinkCutter(int width, int height);
  // All links cut, sorted by (cell, dir), one per (cell, dir): the first segment that cuts a
  // link owns it. `first_segment` gets the global id of each filament's first segment, then
  // the total.
  void cut(const std::vector<Filament>& filaments, WorkerPool& pool, std::vector<CutLink>* links,
           std::vector<int>* first_segment);

 private:
  static constexpr int kSegmentsPerChunk = 128;
  void cut_segment(const Filament& fil, std::size_t k, std::int32_t segment,
                   std::vector<CutLink>& out) const;
  void add(const CutLink& link);
  void sort_by_cell(std::vector<std::int32_t>& cells);
  int width_, height_;
  std::vector<std::uint8_t> mask_;     // per cell: bit d = direction d already cut
  std::vector<std::int32_t> slot_;     // per touched cell: offset of its first link in the output
  std::vector<std::int32_t> touched_;  // cells with a cut link
  std::vector<CutLink> raw_;           // unique links in the order found
  std::vector<std::int32_t> scratch_, count_;
  std::vector<std::pair<std::int32_t, std::int32_t>> segments_;  // (filament, index)
  std::vector<std::vector<CutLink>> found_;                      // per chunk of segments
};

class LatticeBase {
 public:
  LatticeBase(int width, int height, int threads) : pool(threads), cutter(width, height) {}
  virtual ~LatticeBase() = default;
  WorkerPool pool;    // shared by the steps and the link cutting
  LinkCutter cutter;  // scratch of set_filaments, kept to avoid reallocation
  std::vector<CutLink> cut_scratch;
  // One time step; returns the sum of |u|^2 over the bulk (NaN or huge when diverged).
  virtual double step() = 0;
  // `links` sorted by (cell, dir), unique.
  virtual void set_cut_links(const std::vector<CutLink>& links, int segment_count) = 0;
  virtual const std::vector<Vec2>& segment_forces() const = 0;   // by global segment id
  virtual const std::vector<Vec2>& obstacle_forces() const = 0;  // index = label - 1
  virtual void set_inlet(SideName side, const std::vector<Vec2>& per_cell) = 0;
  virtual void set_body_acceleration(const Vec2& g) = 0;
  virtual void set_sponge_velocity(const Vec2& v) = 0;
  virtual void initialize(const Eigen::MatrixXd& rho, const Eigen::MatrixXd& ux,
                          const Eigen::MatrixXd& uy) = 0;
  virtual void read(FlowField& out) const = 0;
  virtual double density(int x, int y) const = 0;
  virtual Vec2 velocity(int x, int y) const = 0;
  virtual double total_mass() const = 0;
  virtual bool streaming_stores() const = 0;
};

// `options` must be valid; `labels` is height x width, 0 fluid, k > 0 obstacle k.
std::unique_ptr<LatticeBase> make_lattice(const Options& options, const Eigen::MatrixXi& labels);

}  // namespace hair25d::fluid
