#include "machine/profile_compressor.hpp"

#include "machine/profile_object_reader.hpp"
#include "machine/profile_units.hpp"

namespace drycut::machine {

using nlohmann::json;

void read_compressor(const json& node, MachineProfile& p) {
  ProfileObjectReader r(node, "compressor");
  CompressorData& c = p.compressor;
  if (auto v = r.quantity("compress_block_path_limit", Dimension::Length))
    c.block_path_limit_mm = require_positive(*v, r.key_path("compress_block_path_limit"));
  if (auto v = r.quantity("compress_velo_tol", Dimension::Velocity))
    c.velo_tol_mm_s = require_non_negative(*v, r.key_path("compress_velo_tol"));
  if (auto v = r.quantity("compress_contur_tol", Dimension::Length))
    c.contur_tol_mm = require_positive(*v, r.key_path("compress_contur_tol"));
  if (auto v = r.integer("compressor_mode")) {
    // Units digit 0..3 (tolerance set), tens 0..3 (value assignments), hundreds 0..3 (circles, G0).
    const long long m = *v;
    if (m < 0 || m > 333 || m % 10 > 3 || m / 10 % 10 > 3)
      r.fail("compressor_mode", "must be a MD20482 value: digits 0..3 (units, tens, hundreds)");
    c.mode = static_cast<int>(m);
  }
  if (auto v = r.quantity("crit_spline_angle", Dimension::Angle))
    c.crit_spline_angle_deg = require_range(*v, 0.0, 89.0, r.key_path("crit_spline_angle"));
  if (auto v = r.integer("max_blocks_per_span")) {
    if (*v < 2 || *v > 1000) r.fail("max_blocks_per_span", "must be in [2, 1000]");
    c.max_blocks_per_span = static_cast<int>(*v);
  }
  if (auto v = r.integer("flush_points")) {
    if (*v < 16 || *v > 1000000) r.fail("flush_points", "must be in [16, 1000000]");
    c.flush_points = static_cast<int>(*v);
  }
  r.reject_unknown_keys();
}

json compressor_to_json(const MachineProfile& p) {
  const CompressorData& c = p.compressor;
  return {{"compress_block_path_limit_mm", c.block_path_limit_mm},
          {"compress_velo_tol_mm_min", c.velo_tol_mm_s * 60.0},
          {"compress_contur_tol_mm", c.contur_tol_mm},
          {"compressor_mode", c.mode},
          {"crit_spline_angle_deg", c.crit_spline_angle_deg},
          {"max_blocks_per_span", c.max_blocks_per_span},
          {"flush_points", c.flush_points}};
}

void read_smoothing(const json& node, MachineProfile& p) {
  ProfileObjectReader r(node, "smoothing");
  SmoothingData& c = p.smoothing;
  if (auto v = r.integer("smoothing_mode")) {
    // Units digit (G643) and tens digit (G642/G645) 0..4; the higher digits (velocity in the
    // rounding block, G644, special settings) are accepted and not modelled.
    const long long m = *v;
    if (m < 0 || m > 99999 || m % 10 > 4 || m / 10 % 10 > 4)
      r.fail("smoothing_mode", "must be a MD20480 value: units and tens digit 0..4");
    c.mode = static_cast<int>(m);
  }
  if (auto v = r.quantity("smooth_contur_tol", Dimension::Length))
    c.contur_tol_mm = require_positive(*v, r.key_path("smooth_contur_tol"));
  if (auto v = r.quantity("smooth_ori_tol", Dimension::Angle))
    c.ori_tol_deg = require_positive(*v, r.key_path("smooth_ori_tol"));
  if (auto v = r.boolean("ignore_ovl_factor_for_adis")) c.ignore_ovl_factor = *v;
  if (auto v = r.number("g0_tolerance_factor"))
    c.g0_tolerance_factor = require_range(*v, 1.0, 1000.0, r.key_path("g0_tolerance_factor"));
  if (auto v = r.integer("mm_max_axispoly_per_block")) {
    if (*v < 0 || *v > 100) r.fail("mm_max_axispoly_per_block", "must be in [0, 100]");
    c.max_axispoly_per_block = static_cast<int>(*v);
  }
  if (auto v = r.number("max_block_share"))
    c.max_block_share = require_range(*v, 0.01, 0.5, r.key_path("max_block_share"));
  if (auto v = r.number("adis_max_reduction"))
    c.adis_max_reduction = require_range(*v, 0.0, 1.0, r.key_path("adis_max_reduction"));
  r.reject_unknown_keys();
}

json smoothing_to_json(const MachineProfile& p) {
  const SmoothingData& c = p.smoothing;
  return {{"smoothing_mode", c.mode},
          {"smooth_contur_tol_mm", c.contur_tol_mm},
          {"smooth_ori_tol_deg", c.ori_tol_deg},
          {"ignore_ovl_factor_for_adis", c.ignore_ovl_factor},
          {"g0_tolerance_factor", c.g0_tolerance_factor},
          {"mm_max_axispoly_per_block", c.max_axispoly_per_block},
          {"max_block_share", c.max_block_share},
          {"adis_max_reduction", c.adis_max_reduction}};
}

}  // namespace drycut::machine
