#include "anchorbench/sim/environment.hpp"

namespace anchorbench::sim {
namespace {

// Messages name the key first ("length_m must be > 0"), so a config reader can point at it.
bool Fail(std::string* why, const char* message) {
  if (why) *why = message;
  return false;
}

// The keys tunnels and halls share: a box and the anchors on its walls.
template <typename Box>
bool ValidBox(const Box& o, std::string* why) {
  // Up to 100 km: beyond any building or tunnel, and far from where metres lose their centimetres.
  if (!(o.length_m > 0.0 && o.length_m <= 1e5)) return Fail(why, "length_m must be in (0, 1e5]");
  if (!(o.width_m > 0.0 && o.width_m <= 1e5)) return Fail(why, "width_m must be in (0, 1e5]");
  if (!(o.height_m > 0.0 && o.height_m <= 1e5)) return Fail(why, "height_m must be in (0, 1e5]");
  if (o.num_anchors < 1 || o.num_anchors > kMaxAnchors) return Fail(why, "num_anchors must be in [1, 10000]");
  if (!(o.anchor_height_min_m >= 0.0)) return Fail(why, "anchor_height_min_m must be >= 0");
  if (!(o.anchor_height_max_m >= o.anchor_height_min_m && o.anchor_height_max_m <= o.height_m)) {
    return Fail(why, "anchor_height_max_m must be in [anchor_height_min_m, height_m]");
  }
  return true;
}

}  // namespace

bool TunnelOptions::IsValid(std::string* why) const {
  if (!ValidBox(*this, why)) return false;
  if (!(along_jitter_m >= 0.0 && along_jitter_m <= length_m)) return Fail(why, "along_jitter_m must be in [0, length_m]");
  return true;
}

bool HallOptions::IsValid(std::string* why) const { return ValidBox(*this, why); }

}  // namespace anchorbench::sim
