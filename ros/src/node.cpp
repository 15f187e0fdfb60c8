// anchorbench_ros: the online front end on a robot (docs/ros.md). Tag poses and UWB ranges in, each
// anchor's estimate out once the configured trigger initializes it, with what every other anchor
// waits for. Solves run on a worker thread with a time budget; callbacks only add samples.
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/Range.h>
#include <std_msgs/Int32.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>
#include <visualization_msgs/MarkerArray.h>

#include "anchor_map.hpp"
#include "settings.hpp"

namespace anchorbench::ros_node {
namespace {

Eigen::Vector3d Position(const geometry_msgs::Point& p) { return {p.x, p.y, p.z}; }
Eigen::Vector3d Position(const geometry_msgs::Vector3& p) { return {p.x, p.y, p.z}; }
Eigen::Quaterniond Orientation(const geometry_msgs::Quaternion& q) {
  const Eigen::Quaterniond r(q.w, q.x, q.y, q.z);
  return r.norm() > 0.5 ? r.normalized() : Eigen::Quaterniond::Identity();  // an unset quaternion: no rotation
}

class Node {
 public:
  Node(ros::NodeHandle& nh, ros::NodeHandle& private_nh, NodeSettings settings)
      : settings_(std::move(settings)), map_(settings_.config, settings_.overrides, settings_.trigger) {
    for (const TagSettings& tag : settings_.tags) {
      SubscribePoses(nh, tag);
      SubscribeRanges(nh, tag);
    }
    markers_ = private_nh.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
    guidance_ = private_nh.advertise<visualization_msgs::MarkerArray>("guidance", 1, true);
    waypoints_ = private_nh.advertise<geometry_msgs::PoseArray>("waypoints", 1, true);
    diagnostics_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    reset_ = private_nh.advertiseService("reset", &Node::OnReset, this);
    save_ = private_nh.advertiseService("save", &Node::OnSave, this);
    reset_anchor_ = private_nh.subscribe("reset_anchor", 10, &Node::OnResetAnchor, this);
    private_nh_ = private_nh;
    diagnostics_timer_ =
        nh.createWallTimer(ros::WallDuration(1.0 / settings_.diagnostics_rate_hz), [this](const ros::WallTimerEvent&) {
          PublishDiagnostics();
          PublishGuidance();
        });
    if (!tf_tags_.empty()) {
      // The node's own listener: each /tf message is in the buffer before its bodies are looked up.
      tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
      tf_subscriber_ = nh.subscribe<tf2_msgs::TFMessage>(
          "/tf", 1000, [this](const tf2_msgs::TFMessage::ConstPtr& m) { OnTf(*m, /*is_static=*/false); });
      tf_static_subscriber_ = nh.subscribe<tf2_msgs::TFMessage>(
          "/tf_static", 100, [this](const tf2_msgs::TFMessage::ConstPtr& m) { OnTf(*m, /*is_static=*/true); });
    }
    worker_ = std::thread([this] { SolveLoop(); });
    ROS_INFO("anchorbench_ros: publishing the '%s' trigger's anchors for %zu tag(s)", map_.trigger().c_str(),
             settings_.tags.size());
  }
  ~Node() {
    stop_ = true;
    if (worker_.joinable()) worker_.join();
  }

 private:
  void SubscribePoses(ros::NodeHandle& nh, const TagSettings& tag) {
    const int id = tag.id;
    const Eigen::Vector3d offset = tag.offset_m;
    auto add = [this, id, offset](const ros::Time& stamp, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
      map_.AddPose(stamp.toSec(), id, p + q * offset);  // the antenna, at its body-frame offset
    };
    if (tag.pose_type == "tf") {
      tf_tags_.push_back({tag.id, Bare(tag.body_frame), tag.offset_m});
    } else if (tag.pose_type == "PoseStamped") {
      subscribers_.push_back(nh.subscribe<geometry_msgs::PoseStamped>(
          tag.pose_topic, 1000, [add](const geometry_msgs::PoseStamped::ConstPtr& m) {
            add(m->header.stamp, Position(m->pose.position), Orientation(m->pose.orientation));
          }));
    } else if (tag.pose_type == "PoseWithCovarianceStamped") {
      subscribers_.push_back(nh.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
          tag.pose_topic, 1000, [add](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
            add(m->header.stamp, Position(m->pose.pose.position), Orientation(m->pose.pose.orientation));
          }));
    } else if (tag.pose_type == "TransformStamped") {
      subscribers_.push_back(nh.subscribe<geometry_msgs::TransformStamped>(
          tag.pose_topic, 1000, [add](const geometry_msgs::TransformStamped::ConstPtr& m) {
            add(m->header.stamp, Position(m->transform.translation), Orientation(m->transform.rotation));
          }));
    } else {  // Odometry (settings.cpp refuses any other name)
      subscribers_.push_back(nh.subscribe<nav_msgs::Odometry>(
          tag.pose_topic, 1000, [add](const nav_msgs::Odometry::ConstPtr& m) {
            add(m->header.stamp, Position(m->pose.pose.position), Orientation(m->pose.pose.orientation));
          }));
    }
  }

  // One topic of all anchors (the id in frame_id), and topics of one anchor each.
  void SubscribeRanges(ros::NodeHandle& nh, const TagSettings& tag) {
    const int id = tag.id;
    if (!tag.range_topic.empty()) {
      subscribers_.push_back(nh.subscribe<sensor_msgs::Range>(
          tag.range_topic, 1000, [this, id](const sensor_msgs::Range::ConstPtr& m) { OnRange(id, std::nullopt, *m); }));
    }
    for (const AnchorTopic& topic : tag.anchor_topics) {
      const int anchor_id = topic.anchor_id;
      subscribers_.push_back(nh.subscribe<sensor_msgs::Range>(
          topic.topic, 1000, [this, id, anchor_id](const sensor_msgs::Range::ConstPtr& m) { OnRange(id, anchor_id, *m); }));
    }
  }

  // A range the front end can use, or one counted as malformed (the node keeps running).
  void OnRange(int tag_id, std::optional<int> anchor_id, const sensor_msgs::Range& m) {
    if (!anchor_id) anchor_id = AnchorIdFromFrame(m.header.frame_id);
    const char* why = nullptr;
    if (!anchor_id) {
      why = "its frame_id names no anchor id (trailing digits)";
    } else if (!std::isfinite(m.range) || m.range <= 0.0f) {
      why = "its range is not a positive finite number";
    } else if (m.max_range > m.min_range && (m.range < m.min_range || m.range > m.max_range)) {
      why = "its range lies outside the message's [min_range, max_range]";
    }
    if (why) {
      map_.CountMalformedRange();
      ROS_WARN_THROTTLE(5.0, "anchorbench_ros: a range of tag %d skipped (frame_id '%s'): %s; counted in /diagnostics",
                        tag_id, m.header.frame_id.c_str(), why);
      return;
    }
    map_.AddRange(m.header.stamp.toSec(), tag_id, *anchor_id, m.range);
  }

  // tf poses: each transform that moves a tag's body gives a pose at its stamp, the body looked up
  // in frame_id through the buffer (static transforms and other dynamic ones on the way).
  void OnTf(const tf2_msgs::TFMessage& message, bool is_static) {
    for (const geometry_msgs::TransformStamped& t : message.transforms) tf_buffer_->setTransform(t, "tf", is_static);
    for (const geometry_msgs::TransformStamped& t : message.transforms) {
      for (const TfTag& tag : tf_tags_) {
        if (Bare(t.child_frame_id) != tag.body_frame) continue;
        geometry_msgs::TransformStamped body;
        try {
          body = tf_buffer_->lookupTransform(settings_.frame_id, tag.body_frame, t.header.stamp);
        } catch (const tf2::TransformException& e) {
          ++tf_failures_;
          ROS_WARN_THROTTLE(5.0, "anchorbench_ros: tag %d's pose skipped: %s", tag.id, e.what());
          continue;
        }
        const Eigen::Quaterniond q = Orientation(body.transform.rotation);
        map_.AddPose(t.header.stamp.toSec(), tag.id, Position(body.transform.translation) + q * tag.offset_m);
      }
    }
  }
  static std::string Bare(const std::string& frame) { return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame; }

  // Solves off the callbacks: a few at a time within a budget, then the new anchors out.
  void SolveLoop() {
    const auto period = std::chrono::duration<double>(1.0 / settings_.solve_rate_hz);
    while (!stop_ && ros::ok()) {
      const auto start = AnchorMap::Clock::now();
      const auto budget = std::chrono::duration_cast<AnchorMap::Clock::duration>(
          std::chrono::duration<double>(settings_.solve_budget_s));
      const std::vector<AnchorState> fresh = map_.Step(settings_.max_solves_per_step, start + budget);
      for (const AnchorState& anchor : fresh) PublishAnchor(anchor);
      if (!fresh.empty()) PublishMarkers();
      std::this_thread::sleep_until(start + std::chrono::duration_cast<AnchorMap::Clock::duration>(period));
    }
  }

  void PublishAnchor(const AnchorState& anchor) {
    auto found = anchor_publishers_.find(anchor.anchor_id);
    if (found == anchor_publishers_.end()) {
      found = anchor_publishers_
                  .emplace(anchor.anchor_id, private_nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>(
                                                 "anchor_" + std::to_string(anchor.anchor_id), 1, true))
                  .first;
    }
    geometry_msgs::PoseWithCovarianceStamped message;
    message.header.stamp = ros::Time(anchor.t_init_s);
    message.header.frame_id = settings_.frame_id;
    const AnchorState& s = anchor;
    message.pose.pose.position.x = s.p_world_anchor.x();
    message.pose.pose.position.y = s.p_world_anchor.y();
    message.pose.pose.position.z = s.p_world_anchor.z();
    message.pose.pose.orientation.w = 1.0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) message.pose.covariance[static_cast<std::size_t>(6 * i + j)] = s.covariance(i, j);
    }
    for (int i = 3; i < 6; ++i) message.pose.covariance[static_cast<std::size_t>(7 * i)] = -1.0;  // no orientation
    found->second.publish(message);
    ROS_INFO("anchorbench_ros: anchor %d at (%.3f, %.3f, %.3f), bias %.3f m, %d samples", anchor.anchor_id,
             s.p_world_anchor.x(), s.p_world_anchor.y(), s.p_world_anchor.z(), s.bias_m, anchor.n_used);
  }

  // A text label above a marker (the next id), `height_m` high.
  static visualization_msgs::Marker LabelOf(const visualization_msgs::Marker& marker, const std::string& text,
                                            double height_m) {
    visualization_msgs::Marker label = marker;
    label.id = marker.id + 1;
    label.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    label.pose.orientation = geometry_msgs::Quaternion();
    label.pose.orientation.w = 1.0;
    label.pose.position.z += marker.scale.z / 2 + 0.15;
    label.scale.x = label.scale.y = 0.0;
    label.scale.z = height_m;  // text height
    label.color.a = 1.0f;
    label.text = text;
    return label;
  }

  // Per initialized anchor: its 99% ellipsoid, coloured by the solve's status, and a label.
  void PublishMarkers() {
    visualization_msgs::MarkerArray array;
    visualization_msgs::Marker clear;  // the anchors a reset removed go too
    clear.action = visualization_msgs::Marker::DELETEALL;
    array.markers.push_back(clear);
    for (const AnchorState& anchor : map_.States()) {
      if (!anchor.initialized) continue;
      visualization_msgs::Marker m;
      m.header.frame_id = settings_.frame_id;
      m.header.stamp = ros::Time::now();
      m.ns = "anchorbench";
      m.id = 2 * anchor.anchor_id;
      m.type = visualization_msgs::Marker::SPHERE;  // the 99% ellipsoid around the estimate
      m.pose.position.x = anchor.p_world_anchor.x();
      m.pose.position.y = anchor.p_world_anchor.y();
      m.pose.position.z = anchor.p_world_anchor.z();
      const Ellipsoid e = EllipsoidOf(anchor.covariance);
      m.pose.orientation.w = e.orientation.w();
      m.pose.orientation.x = e.orientation.x();
      m.pose.orientation.y = e.orientation.y();
      m.pose.orientation.z = e.orientation.z();
      m.scale.x = std::max(e.diameters_m.x(), 0.05);
      m.scale.y = std::max(e.diameters_m.y(), 0.05);
      m.scale.z = std::max(e.diameters_m.z(), 0.05);
      const bool converged = anchor.status == "converged";  // green; max_iterations: amber
      m.color.r = converged ? 0.1f : 1.0f;
      m.color.g = converged ? 0.8f : 0.6f;
      m.color.b = 0.1f;
      m.color.a = 0.5f;
      array.markers.push_back(m);
      array.markers.push_back(
          LabelOf(m, "anchor " + std::to_string(anchor.anchor_id) + " (" + anchor.status + ")", 0.2));
    }
    markers_.publish(array);
  }

  // Per anchor the trigger still waits for, where to range from next (docs/guidance.md): its best
  // candidate as a sphere, labelled with the seconds to certify and the test that holds it now;
  // and for a planner, those that close a region as waypoints, the soonest first.
  void PublishGuidance() {
    if (!(settings_.guidance_reach_m > 0.0)) return;
    const std::vector<AnchorGuide> guides = map_.Guide(settings_.guidance_reach_m, 2, 1, settings_.guidance_range_rate_hz);
    geometry_msgs::PoseArray waypoints;
    waypoints.header.frame_id = settings_.frame_id;
    waypoints.header.stamp = ros::Time::now();
    for (const Eigen::Vector3d& p : WaypointsOf(guides)) {
      geometry_msgs::Pose pose;
      pose.position.x = p.x();
      pose.position.y = p.y();
      pose.position.z = p.z();
      pose.orientation.w = 1.0;
      waypoints.poses.push_back(pose);
    }
    waypoints_.publish(waypoints);
    visualization_msgs::MarkerArray array;
    visualization_msgs::Marker clear;  // anchors initialized since the last step lose theirs
    clear.action = visualization_msgs::Marker::DELETEALL;
    array.markers.push_back(clear);
    for (const AnchorGuide& guide : guides) {
      if (guide.p_world_candidate.empty()) continue;
      visualization_msgs::Marker m;
      m.header.frame_id = settings_.frame_id;
      m.header.stamp = ros::Time::now();
      m.ns = "anchorbench_guidance";
      m.id = 2 * guide.anchor_id;
      m.type = visualization_msgs::Marker::SPHERE;
      m.pose.position.x = guide.p_world_candidate[0].x();
      m.pose.position.y = guide.p_world_candidate[0].y();
      m.pose.position.z = guide.p_world_candidate[0].z();
      m.pose.orientation.w = 1.0;
      m.scale.x = m.scale.y = m.scale.z = 0.2;
      m.color.r = 0.2f;
      m.color.g = 0.4f;
      m.color.b = 1.0f;
      m.color.a = 0.8f;
      array.markers.push_back(m);
      const std::string here = std::isfinite(guide.seconds_to_certify)
                                   ? std::to_string(static_cast<int>(std::ceil(guide.seconds_to_certify))) + " s here"
                                   : std::string("no candidate closes it");
      array.markers.push_back(
          LabelOf(m, "anchor " + std::to_string(guide.anchor_id) + ": " + here + " (held by " + guide.blocked_by + ")", 0.15));
    }
    guidance_.publish(array);
  }

  void PublishDiagnostics() {
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time::now();
    for (const AnchorState& anchor : map_.States()) {
      diagnostic_msgs::DiagnosticStatus status;
      status.name = "anchorbench: anchor " + std::to_string(anchor.anchor_id);
      status.hardware_id = "uwb_anchor_" + std::to_string(anchor.anchor_id);
      status.level = anchor.initialized ? diagnostic_msgs::DiagnosticStatus::OK : diagnostic_msgs::DiagnosticStatus::WARN;
      status.message = anchor.initialized ? "initialized" : "waiting: " + anchor.waiting_for;
      auto value = [&status](const std::string& key, const std::string& text) {
        diagnostic_msgs::KeyValue kv;
        kv.key = key;
        kv.value = text;
        status.values.push_back(kv);
      };
      value("trigger", map_.trigger());
      value("samples", std::to_string(anchor.initialized ? anchor.n_used : anchor.samples));
      if (anchor.initialized) {
        value("bias_m", std::to_string(anchor.bias_m));
        value("t_init_s", std::to_string(anchor.t_init_s));
        value("status", anchor.status);
      } else {
        value("waiting_for", anchor.waiting_for);
      }
      array.status.push_back(status);
    }
    array.status.push_back(InputStatus());
    diagnostics_.publish(array);
  }

  diagnostic_msgs::DiagnosticStatus InputStatus() {
    const InputCounts c = map_.Counts();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = "anchorbench: input";
    status.hardware_id = "anchorbench";
    const long dropped = c.malformed_ranges + c.ranges_outside_poses + c.ranges_without_pose + c.ranges_beyond_max_anchors;
    status.level = dropped > 0 ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK;
    status.message = dropped > 0 ? std::to_string(dropped) + " range(s) not used" : "every range used";
    const std::pair<const char*, long> values[] = {
        {"poses", c.poses}, {"ranges", c.ranges}, {"samples", c.samples}, {"malformed_ranges", c.malformed_ranges},
        {"ranges_outside_poses", c.ranges_outside_poses}, {"ranges_without_pose", c.ranges_without_pose},
        {"poses_ignored", c.poses_ignored}, {"ranges_beyond_max_anchors", c.ranges_beyond_max_anchors},
        {"tf_lookups_failed", tf_failures_.load()}};
    for (const auto& [key, count] : values) {
      diagnostic_msgs::KeyValue kv;
      kv.key = key;
      kv.value = std::to_string(count);
      status.values.push_back(kv);
    }
    return status;
  }

  bool OnReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    map_.Reset();
    PublishMarkers();
    ROS_INFO("anchorbench_ros: every anchor starts over");
    return true;
  }
  void OnResetAnchor(const std_msgs::Int32::ConstPtr& message) {
    if (!map_.Reset(message->data)) ROS_WARN("anchorbench_ros: reset_anchor %d: no such anchor", message->data);
    PublishMarkers();
  }
  bool OnSave(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
    const std::vector<AnchorState> states = map_.States();
    try {
      SaveAnchors(settings_.save_dir.string(), states, settings_.frame_id);
      response.success = true;
      response.message = "wrote " + (settings_.save_dir / "anchors.csv").string() + " and anchors.yaml";
    } catch (const std::exception& e) {
      response.success = false;
      response.message = e.what();
    }
    return true;
  }

  struct TfTag {
    int id;
    std::string body_frame;
    Eigen::Vector3d offset_m;
  };

  NodeSettings settings_;
  AnchorMap map_;
  std::vector<TfTag> tf_tags_;
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  ros::Subscriber tf_subscriber_, tf_static_subscriber_;
  std::atomic<long> tf_failures_{0};
  ros::NodeHandle private_nh_;
  std::vector<ros::Subscriber> subscribers_;
  ros::Subscriber reset_anchor_;
  ros::Publisher markers_, guidance_, waypoints_, diagnostics_;
  std::map<int, ros::Publisher> anchor_publishers_;
  ros::ServiceServer reset_, save_;
  ros::WallTimer diagnostics_timer_;
  std::atomic<bool> stop_{false};
  std::thread worker_;
};

}  // namespace
}  // namespace anchorbench::ros_node

int main(int argc, char** argv) {
  ros::init(argc, argv, "anchorbench");
  ros::NodeHandle nh, private_nh("~");
  using namespace anchorbench;
  try {
    ros_node::NodeSettings settings = ros_node::ReadSettings(private_nh);
    if (settings.solve_max_passes > 0) {  // live: every solve's work bounded (after the config's overrides)
      settings.overrides.push_back("estimator.nls.max_passes=" + std::to_string(settings.solve_max_passes));
    }
    ros_node::Node node(nh, private_nh, std::move(settings));
    ros::spin();
  } catch (const ros_node::BadSetting& e) {
    ROS_FATAL("anchorbench_ros: %s", e.what());
    return 2;
  }
  return 0;
}
