#include "ari_social_sim/dialogue/json_lines.hpp"

#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/core/json_string.hpp"

namespace ari_social_sim::dialogue {
namespace {

using core::json_string;

std::string fixed3(double value) {
  return core::format_text("%.3f", value);
}

std::string string_list(const std::vector<std::string>& items) {
  std::string out = "[";
  for (size_t i = 0; i < items.size(); ++i) {
    out += (i ? "," : "") + json_string(items[i]);
  }
  return out + "]";
}

std::string addressee_value(const std::vector<std::string>& addressees) {
  return addressees.size() == 1 ? json_string(addressees.front()) : string_list(addressees);
}

std::string act_list(const std::vector<DialogueAct>& acts) {
  std::vector<std::string> texts;
  texts.reserve(acts.size());
  for (const DialogueAct& act : acts) {
    texts.push_back(act.to_string());
  }
  return string_list(texts);
}

}  // namespace

std::string utterance_json(int dialogue, const Utterance& u) {
  std::vector<std::string> goals;
  for (const GoalLabel& label : u.goals) {
    goals.push_back(label.to_string());
  }
  std::string out =
      "{\"dialogue\":" + std::to_string(dialogue) + ",\"turn\":" + std::to_string(u.turn) +
      ",\"speaker\":" + json_string(u.speaker) + ",\"addressee\":" + addressee_value(u.addressees) +
      ",\"text\":" + json_string(u.text) + ",\"acts\":" + act_list(u.acts) +
      ",\"goals\":" + string_list(goals) + ",\"start_s\":" + fixed3(u.start_s) +
      ",\"end_s\":" + fixed3(u.end_s);
  if (!u.is_robot()) {
    const Perception& h = u.heard;
    out += ",\"heard\":{\"dropped\":" + std::string(h.dropped ? "true" : "false");
    if (!h.dropped) {
      out += ",\"speaker\":" + json_string(h.speaker) +
             ",\"addressee\":" + addressee_value(h.addressees) +
             ",\"text\":" + json_string(h.text) + ",\"acts\":" + act_list(h.acts) +
             ",\"confidence\":" + fixed3(h.confidence);
    }
    out += "}";
  }
  return out + "}";
}

}  // namespace ari_social_sim::dialogue
