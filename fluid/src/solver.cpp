#include "hair25d/fluid/solver.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hair25d/core/error.h"
#include "lattice.h"

namespace hair25d::fluid {
namespace {

std::string vec_str(const Vec2& v) {
  std::ostringstream s;
  s << "(" << v.x() << ", " << v.y() << ")";
  return s.str();
}

// Obstacle labels of every cell: the mask, then one label per polygon (node inside).
Eigen::MatrixXi rasterize_obstacles(const Options& o) {
  Eigen::MatrixXi labels =
      o.obstacle_labels.size() ? o.obstacle_labels : Eigen::MatrixXi::Zero(o.height, o.width);
  int next = labels.size() ? labels.maxCoeff() + 1 : 1;
  for (const Polyline& poly : o.obstacle_polygons) {
    double x0 = poly[0].x(), x1 = x0, y0 = poly[0].y(), y1 = y0;
    for (const Vec2& p : poly) {
      x0 = std::min(x0, p.x());
      x1 = std::max(x1, p.x());
      y0 = std::min(y0, p.y());
      y1 = std::max(y1, p.y());
    }
    const int cx0 = std::max(0, static_cast<int>(std::floor(x0 - 0.5)));
    const int cx1 = std::min(o.width - 1, static_cast<int>(std::ceil(x1)));
    const int cy0 = std::max(0, static_cast<int>(std::floor(y0 - 0.5)));
    const int cy1 = std::min(o.height - 1, static_cast<int>(std::ceil(y1)));
    for (int y = cy0; y <= cy1; ++y)
      for (int x = cx0; x <= cx1; ++x)
        if (point_in_polygon(poly, Vec2(x + 0.5, y + 0.5))) labels(y, x) = next;
    ++next;
  }
  return labels;
}

void check_cell(const Options& o, int x, int y, const char* what) {
  if (x < 0 || x >= o.width || y < 0 || y >= o.height) {
    std::ostringstream m;
    m << "fluid::Solver::" << what << ": cell (" << x << ", " << y << ") is outside the " << o.width
      << " x " << o.height << " grid";
    throw Error(m.str());
  }
}

void check_inlet(const Options& o, SideName side, const char* what) {
  if (o.side(side).kind != SideKind::kInlet)
    throw Error(std::string("fluid::Solver::") + what +
                ": the side is not an inlet (Options side kind must be kInlet)");
}

}  // namespace

Solver::Solver(const Options& options) : options_(options) {
  std::string error;
  if (!options_.is_valid(&error)) throw Error(error);
  const Eigen::MatrixXi labels = rasterize_obstacles(options_);
  std::vector<char> present(labels.size() ? labels.maxCoeff() + 1 : 1, 0);
  for (Eigen::Index k = 0; k < labels.size(); ++k) present[labels.data()[k]] = 1;
  for (std::size_t l = 1; l < present.size(); ++l)
    if (present[l]) obstacle_ids_.push_back(static_cast<int>(l));
  lattice_ = make_lattice(options_, labels);
  first_segment_.assign(1, 0);
  initialize_uniform(1.0, Vec2::Zero());
}

Solver::~Solver() = default;
Solver::Solver(Solver&&) noexcept = default;
Solver& Solver::operator=(Solver&&) noexcept = default;

const Options& Solver::options() const { return options_; }
std::int64_t Solver::steps_done() const { return steps_; }

void Solver::step(int steps) {
  if (steps < 0)
    throw Error("fluid::Solver::step: steps = " + std::to_string(steps) + "; must be >= 0");
  if (diverged_) throw Error("fluid::Solver::step: the flow diverged earlier; build a new solver");
  const double cells = static_cast<double>(options_.width) * options_.height;
  for (int s = 0; s < steps; ++s) {
    const double usq = lattice_->step();
    ++steps_;
    // Mean |u|^2 above 0.25 (|u| ~ 0.5, near the speed of sound) never comes back.
    if (!std::isfinite(usq) || usq > 0.25 * cells) {
      diverged_ = true;
      std::ostringstream m;
      m << "fluid::Solver::step: the flow diverged at step " << steps_
        << " (velocity beyond the lattice speed of sound); lower the inlet/wall/filament "
           "speeds or raise fluid::Options::tau (currently "
        << options_.tau << ")";
      throw Error(m.str());
    }
  }
  // Per-segment forces are read after the last step only.
  const std::vector<Vec2>& f = lattice_->segment_forces();
  for (std::size_t k = 0; k < segment_forces_.size(); ++k)
    for (std::size_t s = 0; s < segment_forces_[k].size(); ++s) {
      const int g = first_segment_[k] + static_cast<int>(s);
      SegmentForce& out = segment_forces_[k][s];
      out.force = f[g];
      out.pressure_difference = f[g].dot(segment_normals_[g]) / segment_lengths_[g];
    }
}

void Solver::set_filaments(const std::vector<Filament>& filaments) {
  for (std::size_t k = 0; k < filaments.size(); ++k) {
    const Filament& fil = filaments[k];
    const std::string name = "fluid::Solver::set_filaments: filament " + std::to_string(k);
    if (fil.points.size() < 2)
      throw Error(name + " has " + std::to_string(fil.points.size()) + " points; must have >= 2");
    if (!fil.velocities.empty() && fil.velocities.size() != fil.points.size())
      throw Error(name + " has " + std::to_string(fil.velocities.size()) + " velocities for " +
                  std::to_string(fil.points.size()) + " points; must be empty or one per point");
    for (std::size_t j = 0; j < fil.points.size(); ++j) {
      if (!fil.points[j].allFinite())
        throw Error(name + " point " + std::to_string(j) + " = " + vec_str(fil.points[j]) +
                    "; must be finite");
      if (std::abs(fil.points[j].x()) > 1e6 || std::abs(fil.points[j].y()) > 1e6)
        throw Error(name + " point " + std::to_string(j) + " = " + vec_str(fil.points[j]) +
                    "; must be within 1e6 cells of the grid");
      if (j > 0 && (fil.points[j] - fil.points[j - 1]).norm() < 1e-9)
        throw Error(name + " segment " + std::to_string(j - 1) + " from " +
                    vec_str(fil.points[j - 1]) + " to " + vec_str(fil.points[j]) +
                    " has zero length; segments must be longer than 1e-9 cells");
    }
    for (std::size_t j = 0; j < fil.velocities.size(); ++j)
      if (!fil.velocities[j].allFinite() || fil.velocities[j].norm() > kMaxLatticeSpeed)
        throw Error(name + " velocity " + std::to_string(j) + " = " + vec_str(fil.velocities[j]) +
                    "; must be finite with |v| <= " + std::to_string(kMaxLatticeSpeed) +
                    " cells/step");
  }
  std::vector<int> first;
  lattice_->cutter.cut(filaments, lattice_->pool, &lattice_->cut_scratch, &first);
  const int total = first.back();
  lattice_->set_cut_links(lattice_->cut_scratch, total);
  first_segment_ = std::move(first);
  segment_normals_.resize(total);
  segment_lengths_.resize(total);
  segment_forces_.assign(filaments.size(), {});
  for (std::size_t k = 0; k < filaments.size(); ++k) {
    const Polyline& pts = filaments[k].points;
    segment_forces_[k].assign(pts.size() - 1, SegmentForce{});
    for (std::size_t s = 0; s + 1 < pts.size(); ++s) {
      const int g = first_segment_[k] + static_cast<int>(s);
      const Vec2 d = pts[s + 1] - pts[s];
      segment_lengths_[g] = d.norm();
      segment_normals_[g] = Vec2(-d.y(), d.x()) / d.norm();
    }
  }
}

const std::vector<std::vector<SegmentForce>>& Solver::filament_forces() const {
  return segment_forces_;
}

std::vector<ObstacleForce> Solver::obstacle_forces() const {
  std::vector<ObstacleForce> out;
  const std::vector<Vec2>& forces = lattice_->obstacle_forces();
  for (int l : obstacle_ids_) out.push_back({l, forces[l - 1]});
  return out;
}

void Solver::set_inlet_velocity(SideName side, const Vec2& velocity) {
  check_inlet(options_, side, "set_inlet_velocity");
  const Side& sd = options_.side(side);
  const int n =
      (side == SideName::kLeft || side == SideName::kRight) ? options_.height : options_.width;
  std::vector<Vec2> cells(n, velocity);
  if (!sd.profile.empty())
    for (int k = 0; k < n; ++k) cells[k] = velocity * sd.profile[k];
  set_inlet_velocities(side, cells);
}

void Solver::set_inlet_velocities(SideName side, const std::vector<Vec2>& per_cell) {
  check_inlet(options_, side, "set_inlet_velocities");
  const int n =
      (side == SideName::kLeft || side == SideName::kRight) ? options_.height : options_.width;
  if (static_cast<int>(per_cell.size()) != n)
    throw Error("fluid::Solver::set_inlet_velocities: " + std::to_string(per_cell.size()) +
                " velocities; must be " + std::to_string(n) + " (one per cell along the side)");
  for (std::size_t k = 0; k < per_cell.size(); ++k)
    if (!per_cell[k].allFinite() || per_cell[k].norm() > kMaxLatticeSpeed)
      throw Error("fluid::Solver::set_inlet_velocities: velocity " + std::to_string(k) + " = " +
                  vec_str(per_cell[k]) + "; must be finite with |v| <= " +
                  std::to_string(kMaxLatticeSpeed) + " cells/step");
  lattice_->set_inlet(side, per_cell);
}

void Solver::set_body_acceleration(const Vec2& acceleration) {
  Options copy = options_;
  copy.body_acceleration = acceleration;
  std::string error;
  if (!copy.is_valid(&error)) throw Error(error);
  options_.body_acceleration = acceleration;
  lattice_->set_body_acceleration(acceleration);
}

void Solver::set_sponge_velocity(const Vec2& velocity) {
  // Called every step by the wind: checked here rather than by copying the whole Options.
  if (!velocity.allFinite() || velocity.norm() > kMaxLatticeSpeed)
    throw Error("fluid::Options::sponge_velocity = " + vec_str(velocity) +
                "; must be finite with |v| <= " + std::to_string(kMaxLatticeSpeed));
  options_.sponge_velocity = velocity;
  lattice_->set_sponge_velocity(velocity);
}

void Solver::initialize(const Eigen::MatrixXd& density, const Eigen::MatrixXd& ux,
                        const Eigen::MatrixXd& uy) {
  const Eigen::MatrixXd* fields[3] = {&density, &ux, &uy};
  const char* names[3] = {"density", "ux", "uy"};
  for (int k = 0; k < 3; ++k) {
    if (fields[k]->rows() != options_.height || fields[k]->cols() != options_.width)
      throw Error(std::string("fluid::Solver::initialize: ") + names[k] + " is " +
                  std::to_string(fields[k]->rows()) + " x " + std::to_string(fields[k]->cols()) +
                  "; must be height x width = " + std::to_string(options_.height) + " x " +
                  std::to_string(options_.width));
    if (!fields[k]->allFinite())
      throw Error(std::string("fluid::Solver::initialize: ") + names[k] +
                  " has a NaN or infinite value");
  }
  if (density.minCoeff() <= 0.5 || density.maxCoeff() >= 2.0)
    throw Error("fluid::Solver::initialize: density ranges over [" +
                std::to_string(density.minCoeff()) + ", " + std::to_string(density.maxCoeff()) +
                "]; must stay within (0.5, 2)");
  const double speed = (ux.array().square() + uy.array().square()).sqrt().maxCoeff();
  if (speed > kMaxLatticeSpeed)
    throw Error("fluid::Solver::initialize: max |u| = " + std::to_string(speed) +
                "; must be <= " + std::to_string(kMaxLatticeSpeed) + " cells/step");
  lattice_->initialize(density, ux, uy);
  diverged_ = false;
}

void Solver::initialize_uniform(double density, const Vec2& velocity) {
  const int h = options_.height, w = options_.width;
  initialize(Eigen::MatrixXd::Constant(h, w, density),
             Eigen::MatrixXd::Constant(h, w, velocity.x()),
             Eigen::MatrixXd::Constant(h, w, velocity.y()));
}

FlowField Solver::field() const {
  FlowField f;
  lattice_->read(f);
  return f;
}

double Solver::density(int x, int y) const {
  check_cell(options_, x, y, "density");
  return lattice_->density(x, y);
}

Vec2 Solver::velocity(int x, int y) const {
  check_cell(options_, x, y, "velocity");
  return lattice_->velocity(x, y);
}

double Solver::total_mass() const { return lattice_->total_mass(); }

bool Solver::streaming_stores() const { return lattice_->streaming_stores(); }

}  // namespace hair25d::fluid
