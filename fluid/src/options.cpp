#include <algorithm>
#include <cmath>
#include <sstream>

#include "hair25d/fluid/options.h"
#include "stability.h"

namespace hair25d::fluid {
namespace {

bool fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

std::string vec_str(const Vec2& v) {
  std::ostringstream s;
  s << "(" << v.x() << ", " << v.y() << ")";
  return s.str();
}

const char* side_label(int s) {
  static constexpr const char* kNames[4] = {"left", "right", "top", "bottom"};
  return kNames[s];
}

}  // namespace

double viscosity_of_tau(double tau) { return (tau - 0.5) / 3.0; }
double tau_of_viscosity(double nu) { return 3.0 * nu + 0.5; }

const Side& Options::side(SideName name) const {
  switch (name) {
    case SideName::kLeft:
      return left;
    case SideName::kRight:
      return right;
    case SideName::kTop:
      return top;
    case SideName::kBottom:
      return bottom;
  }
  return left;
}

Side& Options::side(SideName name) {
  return const_cast<Side&>(static_cast<const Options&>(*this).side(name));
}

bool Options::is_valid(std::string* error) const {
  std::ostringstream m;
  if (width < 2 || width > kMaxGridSide) {
    m << "fluid::Options::width = " << width << "; must be in [2, " << kMaxGridSide << "]";
    return fail(error, m.str());
  }
  if (height < 2 || height > kMaxGridSide) {
    m << "fluid::Options::height = " << height << "; must be in [2, " << kMaxGridSide << "]";
    return fail(error, m.str());
  }
  if (static_cast<double>(width) * height > kMaxGridCells) {
    m << "fluid::Options::width x height = " << width << " x " << height << "; must be at most "
      << kMaxGridCells << " cells";
    return fail(error, m.str());
  }
  if (!std::isfinite(tau) || !(tau > 0.5)) {
    m << "fluid::Options::tau = " << tau << "; must be > 0.5 (viscosity (tau - 1/2)/3 > 0)";
    return fail(error, m.str());
  }
  const double min_tau = collision == Collision::kBgk ? kMinTauBgk : kMinTauTrt;
  if (tau < min_tau) {
    m << "fluid::Options::tau = " << tau << "; must be >= " << min_tau << " with "
      << (collision == Collision::kBgk ? "BGK (too close to 1/2 is unstable; TRT allows less)"
                                       : "TRT (too close to 1/2 is unstable)");
    return fail(error, m.str());
  }
  if (tau > kMaxTau) {
    m << "fluid::Options::tau = " << tau << "; must be <= " << kMaxTau
      << " (larger relaxation times smear the walls)";
    return fail(error, m.str());
  }
  if (collision == Collision::kTrt &&
      (!std::isfinite(trt_magic) || !(trt_magic > 0.0) || trt_magic > 1.0)) {
    m << "fluid::Options::trt_magic = " << trt_magic << "; must be in (0, 1] (1/4 or 3/16)";
    return fail(error, m.str());
  }
  if (!std::isfinite(smagorinsky) || smagorinsky < 0.0 || smagorinsky > 0.5) {
    m << "fluid::Options::smagorinsky = " << smagorinsky << "; must be in [0, 0.5] (0 = off)";
    return fail(error, m.str());
  }
  if (threads < 1 || threads > 64) {
    m << "fluid::Options::threads = " << threads << "; must be in [1, 64]";
    return fail(error, m.str());
  }
  if (!body_acceleration.allFinite() || body_acceleration.norm() > kMaxBodyAcceleration) {
    m << "fluid::Options::body_acceleration = " << vec_str(body_acceleration)
      << "; must be finite with norm <= " << kMaxBodyAcceleration;
    return fail(error, m.str());
  }
  if (sponge_width < 0 || sponge_width > std::min(width, height) / 2) {
    m << "fluid::Options::sponge_width = " << sponge_width << "; must be in [0, "
      << std::min(width, height) / 2 << "] (half the smaller grid side)";
    return fail(error, m.str());
  }
  if (!sponge_velocity.allFinite() || sponge_velocity.norm() > kMaxLatticeSpeed) {
    m << "fluid::Options::sponge_velocity = " << vec_str(sponge_velocity)
      << "; must be finite with |v| <= " << kMaxLatticeSpeed;
    return fail(error, m.str());
  }
  const Side* sides[4] = {&left, &right, &top, &bottom};
  for (int s = 0; s < 4; ++s) {
    const Side& sd = *sides[s];
    const std::string name = std::string("fluid::Options::") + side_label(s);
    const int along = s < 2 ? height : width;
    if (!sd.velocity.allFinite() || sd.velocity.norm() > kMaxLatticeSpeed) {
      m << name << ".velocity = " << vec_str(sd.velocity)
        << "; must be finite with |v| <= " << kMaxLatticeSpeed << " cells/step (Mach "
        << kMaxLatticeSpeed * std::sqrt(3.0) << ")";
      return fail(error, m.str());
    }
    if (!sd.profile.empty()) {
      if (sd.kind != SideKind::kInlet) {
        m << name << ".profile has " << sd.profile.size()
          << " values; only an inlet side takes a profile";
        return fail(error, m.str());
      }
      if (static_cast<int>(sd.profile.size()) != along) {
        m << name << ".profile has " << sd.profile.size() << " values; must have " << along
          << " (one per cell along the side)";
        return fail(error, m.str());
      }
      for (std::size_t k = 0; k < sd.profile.size(); ++k) {
        const double p = sd.profile[k];
        if (!std::isfinite(p) || std::abs(p) * sd.velocity.norm() > kMaxLatticeSpeed) {
          m << name << ".profile[" << k << "] = " << p
            << "; must be finite and keep |velocity * profile| <= " << kMaxLatticeSpeed;
          return fail(error, m.str());
        }
      }
    }
    if (sd.kind == SideKind::kPeriodic && sd.velocity.norm() > 0) {
      m << name << ".velocity = " << vec_str(sd.velocity)
        << "; a periodic side has no velocity (use kWall or kInlet)";
      return fail(error, m.str());
    }
  }
  if ((left.kind == SideKind::kPeriodic) != (right.kind == SideKind::kPeriodic)) {
    m << "fluid::Options::left/right kinds differ in periodicity; a periodic side needs a "
         "periodic opposite side";
    return fail(error, m.str());
  }
  if ((top.kind == SideKind::kPeriodic) != (bottom.kind == SideKind::kPeriodic)) {
    m << "fluid::Options::top/bottom kinds differ in periodicity; a periodic side needs a "
         "periodic opposite side";
    return fail(error, m.str());
  }
  if (obstacle_labels.size() != 0) {
    if (obstacle_labels.rows() != height || obstacle_labels.cols() != width) {
      m << "fluid::Options::obstacle_labels is " << obstacle_labels.rows() << " x "
        << obstacle_labels.cols() << "; must be empty or height x width = " << height << " x "
        << width;
      return fail(error, m.str());
    }
    if (obstacle_labels.minCoeff() < 0) {
      m << "fluid::Options::obstacle_labels has " << obstacle_labels.minCoeff()
        << "; labels must be >= 0 (0 = fluid)";
      return fail(error, m.str());
    }
    if (obstacle_labels.maxCoeff() > kMaxObstacles) {
      m << "fluid::Options::obstacle_labels has label " << obstacle_labels.maxCoeff()
        << "; must be <= " << kMaxObstacles;
      return fail(error, m.str());
    }
  }
  for (std::size_t k = 0; k < obstacle_polygons.size(); ++k) {
    const Polyline& poly = obstacle_polygons[k];
    if (poly.size() < 3) {
      m << "fluid::Options::obstacle_polygons[" << k << "] has " << poly.size()
        << " points; must have >= 3";
      return fail(error, m.str());
    }
    for (std::size_t j = 0; j < poly.size(); ++j)
      if (!poly[j].allFinite()) {
        m << "fluid::Options::obstacle_polygons[" << k << "][" << j << "] = " << vec_str(poly[j])
          << "; must be finite";
        return fail(error, m.str());
      }
  }
  if (obstacle_polygons.size() > static_cast<std::size_t>(kMaxObstacles)) {
    m << "fluid::Options::obstacle_polygons has " << obstacle_polygons.size()
      << " polygons; must be <= " << kMaxObstacles;
    return fail(error, m.str());
  }
  if (error) error->clear();
  return true;
}

}  // namespace hair25d::fluid
