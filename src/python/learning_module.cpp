// ari_social_sim._learning: the learning environments' cores for Python (pybind11). The Python
// package ari_social_sim.learning wraps them in the Gymnasium conventions; this module only
// moves numbers between numpy arrays and the cores, and releases the GIL while they run.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/dialogue_env.hpp"
#include "ari_social_sim/dialogue/robot_action_request.hpp"
#include "ari_social_sim/learning/nav_env.hpp"
#include "ari_social_sim/learning/vector_nav_env.hpp"
#include "ari_social_sim/navigation/mlp_policy.hpp"

namespace py = pybind11;
using namespace ari_social_sim;

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) {
    text += (i > 0 ? ", " : "") + std::to_string(array.shape(i));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

// Refuses an array whose shape is not `expected` (a dimension of -1 matches any size).
void check_shape(const std::string& name, const py::array& array,
                 const std::vector<py::ssize_t>& expected, const std::string& expected_text) {
  bool ok = array.ndim() == static_cast<py::ssize_t>(expected.size());
  for (size_t i = 0; ok && i < expected.size(); ++i) {
    ok = array.shape(static_cast<py::ssize_t>(i)) == expected[i];
  }
  if (!ok) {
    throw py::value_error(name + ": expected shape " + expected_text + ", got " +
                          shape_text(array));
  }
}

// join_conversation: success is joining and answering; arrival is the place in the group.
void add_conversation(py::dict& d, const learning::ConversationTaskMetrics& c) {
  d["arrived"] = d["success"];
  d["success"] = c.success;
  d["turn_transitions"] = c.group_talk.turn_transitions;
  d["overlap_share"] = c.group_talk.overlap_share;
  d["listener_gaze_at_speaker"] = c.group_talk.listener_gaze_at_speaker;
  d["ari_floor_share"] = c.group_talk.ari_floor_share;
  d["ari_interruptions"] = c.group_talk.ari_interruptions;
  d["ari_addressed_after_s"] = c.group_talk.ari_addressed_after_s;
  d["ari_entered_in_pause"] = c.group_talk.ari_entered_in_pause;
  d["ari_lines"] = c.ari_lines;
  d["interruptions"] = c.interruptions;
  d["entries"] = c.entries;
  d["intrusions"] = c.intrusions;
  d["questions"] = c.questions;
  d["answers"] = c.answers;
  d["answer_delay_s"] = c.answer_delay_s;
  d["joined"] = c.joined;
}

py::dict metrics_dict(const learning::NavMetrics& m) {
  py::dict d;
  d["success"] = m.arrived;
  d["person_collisions"] = m.person_collisions;
  d["static_collisions"] = m.static_collisions;
  d["collisions"] = m.person_collisions + m.static_collisions;
  d["personal_space_time_s"] = m.personal_space_time_s;
  d["path_length_m"] = m.path_length_m;
  d["ospace_intrusions"] = m.ospace_intrusions;
  d["min_person_distance_m"] = m.min_person_distance_m;
  d["time_s"] = m.time_s;
  d["distance_to_goal_m"] = m.distance_to_goal_m;
  d["goal_perceived"] = m.goal_perceived;
  d["gcff_includes_ari"] = m.gcff_includes_ari;
  d["episode_seed"] = m.episode_seed;
  if (m.conversation) {
    add_conversation(d, *m.conversation);
  }
  return d;
}

// The Python wrappers check that a seed is an integer in [0, 2^64); this only converts it.
std::optional<uint64_t> seed_of(const py::object& seed) {
  if (seed.is_none()) {
    return std::nullopt;
  }
  return seed.cast<unsigned long long>();
}

py::list fields_of(const std::vector<navigation::ObservationField>& observation_fields) {
  py::list fields;
  for (const navigation::ObservationField& f : observation_fields) {
    fields.append(py::make_tuple(f.name, f.offset, f.size, f.low, f.high));
  }
  return fields;
}

std::vector<std::string> act_strings(const std::vector<dialogue::DialogueAct>& acts) {
  std::vector<std::string> out;
  out.reserve(acts.size());
  for (const dialogue::DialogueAct& act : acts) {
    out.push_back(act.to_string());
  }
  return out;
}

// What /sim/dialogue/step's DialogueObservation holds, as Python values.
py::dict observation_dict(const dialogue::Observation& observation) {
  py::list heard;
  for (const dialogue::Perception& p : observation.heard) {
    py::dict utterance;
    utterance["dropped"] = p.dropped;
    utterance["speaker"] = p.speaker;
    utterance["addressees"] = p.addressees;
    utterance["text"] = p.text;
    utterance["acts"] = act_strings(p.acts);
    utterance["confidence"] = p.confidence;
    utterance["word_errors"] = p.word_errors;
    heard.append(utterance);
  }
  py::dict d;
  d["heard"] = heard;
  d["robot_turn"] = observation.robot_turn;
  return d;
}

// DialogueInfo: patience per role.
py::dict info_dict(const dialogue::StepInfo& info, const std::vector<std::string>& roles) {
  py::dict patience;
  for (size_t i = 0; i < roles.size() && i < info.patience.size(); ++i) {
    patience[py::str(roles[i])] = info.patience[i];
  }
  py::dict d;
  d["complete"] = info.complete;
  d["success"] = info.success;
  d["robot_turns"] = info.robot_turns;
  d["utterances"] = info.utterances;
  d["patience"] = patience;
  d["goals"] = info.goals;
  return d;
}

// dialogue_node's rl_env mode in-process: the same DialogueEnv and the same request checks as
// /sim/dialogue/reset and /sim/dialogue/step.
class DialogueEnvCore {
 public:
  explicit DialogueEnvCore(const std::string& settings_file)
      : setup_(dialogue::DialogueSetup::create(dialogue::DialogueConfig::load(settings_file))),
        env_(*setup_) {}

  py::tuple reset(uint64_t seed) {
    const dialogue::Observation observation = env_.reset(seed);
    started_ = true;
    return py::make_tuple(observation_dict(observation), info_dict(env_.current_info(), roles()));
  }

  py::tuple step(const std::vector<std::string>& acts, const std::vector<std::string>& addressees,
                 const std::string& text) {
    if (!started_) {
      throw core::RequestError("no episode: call reset() first");
    }
    if (env_.episode_over()) {
      throw core::RequestError("the episode is over: call reset()");
    }
    const dialogue::StepResult result =
        env_.step(dialogue::robot_action_from(acts, addressees, text, roles()));
    return py::make_tuple(observation_dict(result.observation), result.reward, result.terminated,
                          result.truncated, info_dict(result.info, roles()));
  }

  const std::vector<std::string>& roles() const { return setup_->config.users.roles; }

 private:
  std::unique_ptr<dialogue::DialogueSetup> setup_;
  dialogue::DialogueEnv env_;
  bool started_{false};
};

// core::Error (a bad setting or request) reaches Python as ValueError.
void register_error_translator() {
  // pybind11's translator type takes the exception_ptr by value.
  // NOLINTNEXTLINE(performance-unnecessary-value-param)
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) {
        std::rethrow_exception(error);
      }
    } catch (const core::Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

// A navigation task loaded once and shared by the environments made from it.
void bind_nav_env_setup(py::module_& m) {
  py::class_<learning::NavEnvSetup, std::shared_ptr<learning::NavEnvSetup>>(m, "NavEnvSetup")
      .def_static(
          "load",
          [](const std::string& package_dir, const std::string& task_file,
             const std::string& overrides, const std::string& source) {
            return std::const_pointer_cast<learning::NavEnvSetup>(
                learning::NavEnvSetup::load(package_dir, task_file, overrides, source));
          },
          py::arg("package_dir"), py::arg("task_file"), py::arg("overrides"), py::arg("source"))
      .def_property_readonly("time_limit_s",
                             [](const learning::NavEnvSetup& s) { return s.task.time_limit_s; })
      .def_property_readonly(
          "task",
          [](const learning::NavEnvSetup& s) {
            return std::string(core::choice_name(s.task.task, learning::kNavTaskNames));
          })
      .def_property_readonly("arrival",
                             [](const learning::NavEnvSetup& s) {
                               return py::make_tuple(s.task.arrival.position_tolerance_m,
                                                     s.task.arrival.heading_tolerance_rad);
                             })
      .def_property_readonly("observation_config",
                             [](const learning::NavEnvSetup& s) {
                               const navigation::PolicyObservationConfig& o = s.task.observation;
                               py::dict d;
                               d["nearest_people"] = o.nearest_people;
                               d["patch_cells"] = o.patch_cells;
                               d["patch_resolution"] = o.patch_resolution_m;
                               d["people_range"] = o.people_range_m;
                               return d;
                             })
      .def_property_readonly(
          "step_s", [](const learning::NavEnvSetup&) { return learning::NavEnv::step_s(); })
      .def_property_readonly("action_size", [](const learning::NavEnvSetup& s) {
        return learning::action_size(s.task.task);
      });
}

// The action space and the vector environment's limits.
void bind_nav_constants(py::module_& m) {
  m.def("action_bounds", [] {
    const learning::ActionBounds b = learning::action_bounds();
    return py::make_tuple(std::vector<float>(b.low.begin(), b.low.end()),
                          std::vector<float>(b.high.begin(), b.high.end()));
  });
  m.attr("max_envs") = learning::VectorNavEnv::kMaxEnvs;
  m.attr("max_threads") = learning::VectorNavEnv::kMaxThreads;
  m.attr("action_names") = std::vector<std::string>(std::begin(learning::kActionNames),
                                                    std::end(learning::kActionNames));
  m.attr("speak_name") = std::string(learning::kSpeakName);
}

void bind_nav_env(py::module_& m) {
  py::class_<learning::Env>(m, "NavEnv")
      .def(py::init([](const std::shared_ptr<learning::NavEnvSetup>& setup) {
        return learning::make_env(setup);
      }))
      .def_property_readonly("observation_size", &learning::Env::observation_size)
      .def_property_readonly("action_size", &learning::Env::action_size)
      .def("observation_fields",
           [](const learning::Env& env) { return fields_of(env.observation_fields()); })
      .def(
          "reset",
          [](learning::Env& env, const py::object& seed) {
            const std::optional<uint64_t> s = seed_of(seed);
            FloatArray observation(env.observation_size());
            float* out = observation.mutable_data();
            py::gil_scoped_release release;
            env.reset(s, out);
            return observation;
          },
          py::arg("seed") = py::none())
      .def("step",
           [](learning::Env& env, const py::array& action_in) {
             FloatArray action = FloatArray::ensure(action_in);
             if (!action) {
               throw py::value_error("action: expected an array of numbers");
             }
             check_shape("action", action, {env.action_size()},
                         "(" + std::to_string(env.action_size()) + ",)");
             FloatArray observation(env.observation_size());
             float* out = observation.mutable_data();
             const float* in = action.data();
             learning::NavStepResult result;
             {
               py::gil_scoped_release release;
               result = env.step(in, out);
             }
             return py::make_tuple(observation, result.reward, result.terminated, result.truncated);
           })
      .def("metrics", [](const learning::Env& env) { return metrics_dict(env.metrics()); })
      .def_property_readonly("done", &learning::Env::done);
}

void bind_vector_nav_env(py::module_& m) {
  py::class_<learning::VectorNavEnv>(m, "VectorNavEnv")
      .def(py::init(
               [](const std::shared_ptr<learning::NavEnvSetup>& setup, int num_envs, int threads) {
                 return std::make_unique<learning::VectorNavEnv>(setup, num_envs, threads);
               }),
           py::arg("setup"), py::arg("num_envs"), py::arg("threads"))
      .def_property_readonly("num_envs", &learning::VectorNavEnv::num_envs)
      .def_property_readonly("observation_size", &learning::VectorNavEnv::observation_size)
      .def("observation_fields",
           [](const learning::VectorNavEnv& env) {
             return fields_of(env.env(0).observation_fields());
           })
      .def(
          "reset",
          [](learning::VectorNavEnv& env, const py::object& seed) {
            const std::optional<uint64_t> s = seed_of(seed);
            FloatArray observations({env.num_envs(), env.observation_size()});
            float* out = observations.mutable_data();
            py::gil_scoped_release release;
            env.reset(s, out);
            return observations;
          },
          py::arg("seed") = py::none())
      .def("step",
           [](learning::VectorNavEnv& env, const py::array& actions_in) {
             FloatArray actions = FloatArray::ensure(actions_in);
             if (!actions) {
               throw py::value_error("actions: expected an array of numbers");
             }
             check_shape("actions", actions, {env.num_envs(), env.action_size()},
                         "(" + std::to_string(env.num_envs()) + ", " +
                             std::to_string(env.action_size()) + ")");
             const py::ssize_t n = env.num_envs(), size = env.observation_size();
             FloatArray observations({n, size});
             FloatArray final_observations({n, size});
             // Rows of environments whose episode goes on are zeros, not whatever memory held.
             std::fill(final_observations.mutable_data(),
                       final_observations.mutable_data() + n * size, 0.0f);
             py::array_t<double> rewards(n);
             py::array_t<bool> terminated(n), truncated(n);
             learning::VectorStepOutput out{observations.mutable_data(), rewards.mutable_data(),
                                            terminated.mutable_data(), truncated.mutable_data(),
                                            final_observations.mutable_data()};
             const float* in = actions.data();
             {
               py::gil_scoped_release release;
               env.step(in, out);
             }
             return py::make_tuple(observations, rewards, terminated, truncated,
                                   final_observations);
           })
      .def("metrics", [](const learning::VectorNavEnv& env,
                         int i) { return metrics_dict(env.env(i).metrics()); })
      .def("final_metrics", [](const learning::VectorNavEnv& env, int i) {
        return metrics_dict(env.final_metrics(i));
      });
}

void bind_dialogue_env(py::module_& m) {
  py::class_<DialogueEnvCore>(m, "DialogueEnv")
      .def(py::init<const std::string&>(), py::arg("settings_file"))
      .def("reset", &DialogueEnvCore::reset, py::arg("seed"))
      .def("step", &DialogueEnvCore::step, py::arg("acts"), py::arg("addressees"), py::arg("text"))
      .def_property_readonly("roles", &DialogueEnvCore::roles);
}

void bind_mlp_policy(py::module_& m) {
  py::class_<navigation::MlpPolicy>(m, "MlpPolicy")
      .def(py::init([](const std::string& path) { return navigation::MlpPolicy::load_file(path); }),
           py::arg("path"))
      .def_property_readonly("task", &navigation::MlpPolicy::task)
      .def("act", [](navigation::MlpPolicy& policy, const py::array& observation_in) {
        FloatArray observation = FloatArray::ensure(observation_in);
        const auto size =
            static_cast<py::ssize_t>(navigation::PolicyObservation(policy.observation()).size());
        if (!observation) {
          throw py::value_error("observation: expected an array of numbers");
        }
        check_shape("observation", observation, {size}, "(" + std::to_string(size) + ",)");
        const auto action = policy.act(observation.data());
        return std::vector<double>(action.begin(), action.end());
      });
}

}  // namespace

PYBIND11_MODULE(_learning, m) {
  m.doc() = "Cores of ari_social_sim.learning (use that package, not this module)";
  register_error_translator();
  bind_nav_env_setup(m);
  bind_nav_constants(m);
  bind_nav_env(m);
  bind_vector_nav_env(m);
  bind_dialogue_env(m);
  bind_mlp_policy(m);
}
