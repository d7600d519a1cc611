#pragma once

#include <stdexcept>
#include <string>

namespace ari_social_sim::core {

/// Base of every error the simulator throws on purpose. Thrown where input enters (files,
/// parameters, service requests) and caught at the boundary (node callbacks, tool mains); per-tick
/// code never throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A user-written file or parameter set is malformed. The message names the source (file or
/// parameter namespace), the field path, the value found and what was expected.
class ConfigError : public Error {
 public:
  using Error::Error;
};

/// A request against a running simulation cannot be honoured (unknown id, overlapping spawn, ...).
class RequestError : public Error {
 public:
  using Error::Error;
};

}  // namespace ari_social_sim::core
