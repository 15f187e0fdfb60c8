#pragma once
// The node's ROS parameters (docs/ros.md), read and checked once at start: a bad one is one
// error naming it, before anything is subscribed.

#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <ros/node_handle.h>

namespace anchorbench::ros_node {

// A range topic that carries one anchor only (its frame_id is then not read).
struct AnchorTopic {
  int anchor_id = 0;
  std::string topic;
};

struct TagSettings {
  int id = 0;
  std::string pose_type = "PoseStamped";  // PoseStamped, PoseWithCovarianceStamped, TransformStamped, Odometry, tf
  std::string pose_topic;              // the body's pose (the four message types)
  std::string body_frame;              // tf: the body's frame, looked up in the node's frame_id
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();  // the antenna in the body frame
  std::string range_topic;             // sensor_msgs/Range, the anchor id in header.frame_id
  std::vector<AnchorTopic> anchor_topics;  // and/or one sensor_msgs/Range topic per anchor
};

struct NodeSettings {
  std::string config;                  // the CLI's YAML (empty: the defaults)
  std::vector<std::string> overrides;  // KEY=VALUE, as --set
  std::string trigger;                 // published (empty: certified if listed, else the first online)
  std::string frame_id = "world";
  std::filesystem::path save_dir = ".";
  double solve_rate_hz = 20.0;         // the solve worker's steps
  double solve_budget_s = 0.02;        // no solve starts later than this into a step
  int max_solves_per_step = 8;
  int solve_max_passes = 200;          // each solve's work budget (estimator.nls.max_passes); 0: the config's
  double diagnostics_rate_hz = 1.0;
  double guidance_reach_m = 2.0;        // ~guidance's candidates around the tag (0: no guidance)
  double guidance_range_rate_hz = 10.0;  // a link's ranging rate: samples to certify -> seconds
  std::vector<TagSettings> tags;
};

// Throws BadSetting naming the parameter.
NodeSettings ReadSettings(const ros::NodeHandle& private_nh);

}  // namespace anchorbench::ros_node
