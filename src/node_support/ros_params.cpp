#include "ros_params.hpp"

#include <ros/this_node.h>

#include <sstream>

namespace ari_social_sim::nodes {
namespace {

YAML::Node to_yaml(XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return YAML::Node(static_cast<bool>(value));
    case XmlRpc::XmlRpcValue::TypeInt:
      return YAML::Node(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble: {
      // Through text, so that 0.1 stays 0.1 for the reader's own parsing and messages.
      std::ostringstream out;
      out.precision(17);
      out << static_cast<double>(value);
      return YAML::Node(out.str());
    }
    case XmlRpc::XmlRpcValue::TypeString:
      return YAML::Node(static_cast<std::string>(value));
    case XmlRpc::XmlRpcValue::TypeArray: {
      YAML::Node list(YAML::NodeType::Sequence);
      // Not a range-for: XmlRpcValue's begin() walks a struct's members, not an array's items.
      // NOLINTNEXTLINE(modernize-loop-convert)
      for (int i = 0; i < value.size(); ++i) {
        list.push_back(to_yaml(value[i]));
      }
      return list;
    }
    case XmlRpc::XmlRpcValue::TypeStruct: {
      YAML::Node map(YAML::NodeType::Map);
      for (auto& entry : value) {
        map[entry.first] = to_yaml(entry.second);
      }
      return map;
    }
    default:
      return YAML::Node();
  }
}

}  // namespace

core::YamlMap read_private_params(const ros::NodeHandle& private_handle) {
  XmlRpc::XmlRpcValue params;
  YAML::Node root(YAML::NodeType::Map);
  if (private_handle.getParam("", params) && params.getType() == XmlRpc::XmlRpcValue::TypeStruct) {
    root = to_yaml(params);
  }
  return core::YamlMap(root, ros::this_node::getName() + " parameter");
}

}  // namespace ari_social_sim::nodes
