#include <cmath>
#include <string>

#include "hair25d/completion/completion.h"

namespace hair25d::completion {

bool Options::is_valid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error != nullptr) *error = "completion::Options::" + m;
    return false;
  };
  auto num = [](double v) { return std::to_string(v); };
  if (outline_reach < 0 || outline_reach > 32)
    return fail("outline_reach = " + std::to_string(outline_reach) + "; must be in [0, 32]");
  if (dark_luma < 0 || dark_luma > 256)
    return fail("dark_luma = " + std::to_string(dark_luma) + "; must be in [0, 256]");
  if (cover_fringe < 0 || cover_fringe > 8)
    return fail("cover_fringe = " + std::to_string(cover_fringe) + "; must be in [0, 8]");
  if (!(cover_fringe_layering_cost >= 0 && cover_fringe_layering_cost <= 100))
    return fail("cover_fringe_layering_cost = " + num(cover_fringe_layering_cost) +
                "; must be in [0, 100]");
  if (!(face_piece_mass_step >= 0 && face_piece_mass_step <= 1))
    return fail("face_piece_mass_step = " + num(face_piece_mass_step) + "; must be in [0, 1]");
  if (!(tone_path_landing_share >= 0 && tone_path_landing_share <= 10))
    return fail("tone_path_landing_share = " + num(tone_path_landing_share) +
                "; must be in [0, 10]");
  if (occluder_reach < 0 || occluder_reach > 16)
    return fail("occluder_reach = " + std::to_string(occluder_reach) + "; must be in [0, 16]");
  if (!(merge_gap >= 0)) return fail("merge_gap = " + num(merge_gap) + "; must be >= 0");
  if (!(min_edge_length >= 1))
    return fail("min_edge_length = " + num(min_edge_length) + "; must be >= 1");
  if (!(tangent_arm >= 2)) return fail("tangent_arm = " + num(tangent_arm) + "; must be >= 2");
  if (!(max_join_angle_deg > 0 && max_join_angle_deg <= 180))
    return fail("max_join_angle_deg = " + num(max_join_angle_deg) + "; must be in (0, 180]");
  if (!(max_colour_distance > 0))
    return fail("max_colour_distance = " + num(max_colour_distance) + "; must be > 0");
  if (!(min_join_coverage >= 0 && min_join_coverage <= 1))
    return fail("min_join_coverage = " + num(min_join_coverage) + "; must be in [0, 1]");
  for (double share : join_arm_shares)
    if (!(share > 0 && share <= 1.5))
      return fail("join_arm_shares holds " + num(share) + "; each must be in (0, 1.5]");
  if (!(second_partner_p == 0 || (second_partner_p >= 0.5 && second_partner_p <= 1)))
    return fail("second_partner_p = " + num(second_partner_p) +
                "; must be 0 (never) or in [0.5, 1]");
  if (!(corridor_width >= 0 && corridor_width <= 2))
    return fail("corridor_width = " + num(corridor_width) + "; must be in [0, 2]");
  if (!(corridor_min_probability >= 0 && corridor_min_probability <= 1))
    return fail("corridor_min_probability = " + num(corridor_min_probability) +
                "; must be in [0, 1]");
  if (!(min_width_ratio >= 0 && min_width_ratio <= 1))
    return fail("min_width_ratio = " + num(min_width_ratio) + "; must be in [0, 1]");
  if (!(max_join_cost > 0)) return fail("max_join_cost = " + num(max_join_cost) + "; must be > 0");
  if (!(fit_length >= 3)) return fail("fit_length = " + num(fit_length) + "; must be >= 3");
  if (!(fit_regularization >= 0))
    return fail("fit_regularization = " + num(fit_regularization) + "; must be >= 0");
  if (threads < 1 || threads > 64)
    return fail("threads = " + std::to_string(threads) + "; must be in [1, 64]");
  std::string inner;
  if (!contour.is_valid(&inner)) return fail("contour: " + inner);
  if (!inpaint.is_valid(&inner)) return fail("inpaint: " + inner);
  if (!background.is_valid(&inner)) return fail("background: " + inner);
  if (!join_scorer.is_valid(&inner)) return fail("join_scorer: " + inner);
  return true;
}

}  // namespace hair25d::completion
