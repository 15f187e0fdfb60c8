#pragma once

#include <string>
#include <string_view>

#include "anchorbench/estimator/enum_names.hpp"

namespace anchorbench::sim {

enum class BiasDistribution { kUniform, kNormal };
enum class OutlierKind {
  kPositive,   // NLOS-like: the range is too long by a magnitude in [min, max]
  kSymmetric,  // spikes of either sign
};

inline constexpr estimator::EnumNames<BiasDistribution, 2> kBiasDistributionNames({
    {BiasDistribution::kUniform, "uniform"}, {BiasDistribution::kNormal, "normal"}});
inline std::string_view ToString(BiasDistribution value) { return kBiasDistributionNames.Name(value); }
inline constexpr estimator::EnumNames<OutlierKind, 2> kOutlierKindNames({
    {OutlierKind::kPositive, "positive"}, {OutlierKind::kSymmetric, "symmetric"}});
inline std::string_view ToString(OutlierKind value) { return kOutlierKindNames.Name(value); }
inline bool ParseBiasDistribution(std::string_view name, BiasDistribution* value) { return kBiasDistributionNames.Parse(name, value); }
inline bool ParseOutlierKind(std::string_view name, OutlierKind* value) { return kOutlierKindNames.Parse(name, value); }

// Range model of Eq. (1): d = ||p_U - p_A|| + gamma_A + eta, eta ~ N(0, sigma_d^2), plus outliers,
// and (ours, off by default) what Eq. (1) leaves out: d = (1 + s_A) ||p_U - p_A|| + gamma_A +
// f_A(u_A->U) + g_U(u_U->A, body frame) + o_UA + eta, with f, g antenna patterns, o a link offset.
struct RangeModelOptions {
  double sigma_range_m = 0.1;  // sigma_d
  // Constant per-anchor bias gamma_A: uniform in [bias_a_m, bias_b_m], or normal with
  // mean bias_a_m and standard deviation bias_b_m.
  BiasDistribution bias_distribution = BiasDistribution::kUniform;
  double bias_a_m = -0.3;
  double bias_b_m = 0.3;
  double outlier_probability = 0.0;  // long-run fraction of ranges that are outliers
  // Mean number of consecutive outlier ranges of one episode (geometric); one offset holds for
  // the whole episode, like a sustained NLOS excess path. 1: isolated spikes.
  double outlier_burst_length = 1.0;
  OutlierKind outlier_kind = OutlierKind::kPositive;
  double outlier_min_m = 1.0;  // outlier magnitude, uniform in [min, max]
  double outlier_max_m = 10.0;
  double max_range_m = 40.0;          // anchors farther than this (true distance) give no range
  double dropout_probability = 0.0;   // a range inside max_range is lost with this probability
  double sigma_position_m = 0.0;      // white noise on the reported tag positions (each axis)
  // The biases real radios have (ours, from public recordings: docs/method.md), each off at 0 and
  // drawing nothing then, so the paper's scenarios are untouched:
  double antenna_bias_m = 0.0;      // RMS of each anchor's direction-dependent bias (AntennaPattern)
  double tag_antenna_bias_m = 0.0;  // the same for each tag, in the body frame
  double link_offset_m = 0.0;       // sigma of a constant offset per (tag, anchor) link
  double range_scale_sigma = 0.0;   // sigma of a per-anchor scale error: range += s * distance

  bool IsValid(std::string* why) const;
};

}  // namespace anchorbench::sim
