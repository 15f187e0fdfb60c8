#include "settings.hpp"

#include <cmath>

#include <xmlrpcpp/XmlRpcValue.h>

#include "anchor_map.hpp"

namespace anchorbench::ros_node {
namespace {

[[noreturn]] void Refuse(const std::string& name, const std::string& why) {
  throw BadSetting("parameter ~" + name + ": " + why);
}

double Number(XmlRpc::XmlRpcValue& value, const std::string& name) {
  if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<int>(value);
  if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble) return static_cast<double>(value);
  Refuse(name, "expected a number");
}

std::string Text(XmlRpc::XmlRpcValue& value, const std::string& name) {
  if (value.getType() != XmlRpc::XmlRpcValue::TypeString) Refuse(name, "expected a string");
  return static_cast<std::string>(value);
}

TagSettings Tag(XmlRpc::XmlRpcValue& entry, const std::string& name) {
  if (entry.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
    Refuse(name, "expected {id, pose_topic, pose_type, offset_m, range_topic}");
  }
  TagSettings tag;
  for (auto& [key, value] : entry) {
    const std::string where = name + "." + key;
    if (key == "id") {
      const double id = Number(value, where);
      if (id != std::floor(id) || id < 0 || id > 1e6) Refuse(where, "expected a whole number in [0, 1e6]");
      tag.id = static_cast<int>(id);
    } else if (key == "pose_topic") {
      tag.pose_topic = Text(value, where);
    } else if (key == "pose_type") {
      tag.pose_type = Text(value, where);
      if (tag.pose_type != "PoseStamped" && tag.pose_type != "PoseWithCovarianceStamped" &&
          tag.pose_type != "TransformStamped" && tag.pose_type != "Odometry") {
        Refuse(where, "'" + tag.pose_type + "': one of PoseStamped, PoseWithCovarianceStamped, TransformStamped, Odometry");
      }
    } else if (key == "offset_m") {
      if (value.getType() != XmlRpc::XmlRpcValue::TypeArray || value.size() != 3) Refuse(where, "expected [x, y, z]");
      for (int i = 0; i < 3; ++i) tag.offset_m(i) = Number(value[i], where);
      if (!tag.offset_m.allFinite() || tag.offset_m.norm() > 100.0) Refuse(where, "expected finite metres, at most 100");
    } else if (key == "range_topic") {
      tag.range_topic = Text(value, where);
    } else {
      Refuse(where, "unknown key");
    }
  }
  if (tag.pose_topic.empty()) Refuse(name + ".pose_topic", "missing");
  if (tag.range_topic.empty()) Refuse(name + ".range_topic", "missing");
  return tag;
}

double Positive(const ros::NodeHandle& nh, const std::string& name, double fallback, double max) {
  double value = fallback;
  nh.param(name, value, fallback);
  if (!(value > 0.0 && value <= max)) Refuse(name, "must be in (0, " + std::to_string(max) + "]");
  return value;
}

}  // namespace

NodeSettings ReadSettings(const ros::NodeHandle& nh) {
  NodeSettings s;
  nh.param<std::string>("config", s.config, "");
  nh.param<std::vector<std::string>>("overrides", s.overrides, {});
  nh.param<std::string>("trigger", s.trigger, "");
  nh.param<std::string>("frame_id", s.frame_id, "world");
  std::string save_dir = ".";
  nh.param<std::string>("save_dir", save_dir, ".");
  s.save_dir = save_dir;
  s.solve_rate_hz = Positive(nh, "solve_rate_hz", s.solve_rate_hz, 1000.0);
  s.solve_budget_s = Positive(nh, "solve_budget_s", s.solve_budget_s, 10.0);
  s.max_solves_per_step = static_cast<int>(Positive(nh, "max_solves_per_step", s.max_solves_per_step, 1e6));
  s.diagnostics_rate_hz = Positive(nh, "diagnostics_rate_hz", s.diagnostics_rate_hz, 100.0);
  XmlRpc::XmlRpcValue tags;
  if (!nh.getParam("tags", tags)) Refuse("tags", "missing: a list of {id, pose_topic, pose_type, offset_m, range_topic}");
  if (tags.getType() != XmlRpc::XmlRpcValue::TypeArray || tags.size() == 0) Refuse("tags", "expected a non-empty list");
  for (int i = 0; i < tags.size(); ++i) {
    s.tags.push_back(Tag(tags[i], "tags[" + std::to_string(i) + "]"));
    for (std::size_t j = 0; j + 1 < s.tags.size(); ++j) {
      if (s.tags[j].id == s.tags.back().id) Refuse("tags[" + std::to_string(i) + "].id", "repeats tag " + std::to_string(s.tags[j].id));
    }
  }
  return s;
}

}  // namespace anchorbench::ros_node
