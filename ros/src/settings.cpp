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

int WholeNumber(XmlRpc::XmlRpcValue& value, const std::string& name, double max) {
  const double number = Number(value, name);
  if (number != std::floor(number) || number < 0 || number > max) {
    Refuse(name, "expected a whole number in [0, " + std::to_string(static_cast<long>(max)) + "]");
  }
  return static_cast<int>(number);
}

std::vector<AnchorTopic> AnchorTopics(XmlRpc::XmlRpcValue& list, const std::string& name) {
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray) Refuse(name, "expected a list of {anchor, topic}");
  std::vector<AnchorTopic> topics;
  for (int i = 0; i < list.size(); ++i) {
    const std::string where = name + "[" + std::to_string(i) + "]";
    if (list[i].getType() != XmlRpc::XmlRpcValue::TypeStruct) Refuse(where, "expected {anchor, topic}");
    AnchorTopic entry{-1, ""};
    for (auto& [key, value] : list[i]) {
      if (key == "anchor") {
        entry.anchor_id = WholeNumber(value, where + ".anchor", 1e9);
      } else if (key == "topic") {
        entry.topic = Text(value, where + ".topic");
      } else {
        Refuse(where + "." + key, "unknown key (anchor, topic)");
      }
    }
    if (entry.anchor_id < 0 || entry.topic.empty()) Refuse(where, "expected {anchor, topic}, both given");
    topics.push_back(entry);
  }
  return topics;
}

TagSettings Tag(XmlRpc::XmlRpcValue& entry, const std::string& name) {
  if (entry.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
    Refuse(name, "expected {id, pose_topic, pose_type, offset_m, range_topic}");
  }
  TagSettings tag;
  for (auto& [key, value] : entry) {
    const std::string where = name + "." + key;
    if (key == "id") {
      tag.id = WholeNumber(value, where, 1e6);
    } else if (key == "pose_topic") {
      tag.pose_topic = Text(value, where);
    } else if (key == "body_frame") {
      tag.body_frame = Text(value, where);
    } else if (key == "pose_type") {
      tag.pose_type = Text(value, where);
      if (tag.pose_type != "PoseStamped" && tag.pose_type != "PoseWithCovarianceStamped" &&
          tag.pose_type != "TransformStamped" && tag.pose_type != "Odometry" && tag.pose_type != "tf") {
        Refuse(where, "'" + tag.pose_type +
                          "': one of PoseStamped, PoseWithCovarianceStamped, TransformStamped, Odometry, tf");
      }
    } else if (key == "offset_m") {
      if (value.getType() != XmlRpc::XmlRpcValue::TypeArray || value.size() != 3) Refuse(where, "expected [x, y, z]");
      for (int i = 0; i < 3; ++i) tag.offset_m(i) = Number(value[i], where);
      if (!tag.offset_m.allFinite() || tag.offset_m.norm() > 100.0) Refuse(where, "expected finite metres, at most 100");
    } else if (key == "range_topic") {
      tag.range_topic = Text(value, where);
    } else if (key == "range_topics") {
      tag.anchor_topics = AnchorTopics(value, where);
    } else {
      Refuse(where, "unknown key");
    }
  }
  if (tag.pose_type == "tf") {
    if (tag.body_frame.empty()) Refuse(name + ".body_frame", "missing: pose_type tf looks the body's frame up");
    if (!tag.pose_topic.empty()) Refuse(name + ".pose_topic", "not read with pose_type tf (body_frame is)");
  } else if (tag.pose_topic.empty()) {
    Refuse(name + ".pose_topic", "missing");
  }
  if (tag.range_topic.empty() && tag.anchor_topics.empty()) {
    Refuse(name + ".range_topic", "missing: a range_topic, or range_topics [{anchor, topic}]");
  }
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
  nh.param("guidance_reach_m", s.guidance_reach_m, s.guidance_reach_m);
  if (!(s.guidance_reach_m >= 0.0 && s.guidance_reach_m <= 1000.0)) Refuse("guidance_reach_m", "must be in [0, 1000]");
  s.guidance_range_rate_hz = Positive(nh, "guidance_range_rate_hz", s.guidance_range_rate_hz, 10000.0);
  nh.param("solve_max_passes", s.solve_max_passes, s.solve_max_passes);
  if (s.solve_max_passes < 0 || s.solve_max_passes > 100000000) Refuse("solve_max_passes", "must be in [0, 1e8]");
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
