#include "ari_social_sim/world_speech/small_talk_lines.hpp"

namespace ari_social_sim::world_speech {
namespace {

// Chance a question to one person starts with their name, as people call on someone in a group.
constexpr double kNameTheAddressee = 0.3;

}  // namespace

SmallTalkLines::SmallTalkLines(dialogue::SmallTalk talk, dialogue::Domain domain, dialogue::Nlg nlg)
    : talk_(std::move(talk)), domain_(std::move(domain)), nlg_(std::move(nlg)) {}

std::shared_ptr<const SmallTalkLines> SmallTalkLines::load(const std::string& config_dir) {
  const std::string dir = config_dir + "/dialogue/";
  return std::make_shared<const SmallTalkLines>(
      dialogue::SmallTalk::load(dir + "small_talk.yaml"),
      dialogue::Domain::load(dir + "hospital_domain.yaml"),
      dialogue::Nlg(dialogue::NlgTemplates::load(dir + "nlg_templates.yaml"), nullptr,
                    dialogue::NlgMode::kTemplate));
}

world::ConversationLine SmallTalkLines::line(world::LineKind kind,
                                             const std::string& addressee_name,
                                             core::Rng& rng) const {
  switch (kind) {
    case world::LineKind::kRobotQuestion:
      return robot_question(rng);
    case world::LineKind::kBackchannel:
      return {"backchannel()", talk_.draw(talk_.backchannels, rng)};
    case world::LineKind::kAnswer:
      return {"answer(small_talk)", talk_.draw(talk_.answers, rng)};
    case world::LineKind::kQuestion: {
      std::string text = talk_.draw(talk_.questions, rng);
      if (!addressee_name.empty() && rng.bernoulli(kNameTheAddressee)) {
        text = addressee_name + ", " + text;
      }
      return {"question(small_talk)", text};
    }
    case world::LineKind::kStatement:
      break;
  }
  return {"inform(small_talk)", talk_.draw(talk_.statements, rng)};
}

world::ConversationLine SmallTalkLines::robot_question(core::Rng& rng) const {
  const dialogue::Goal goal = domain_.sample_goal({}, rng);
  const std::vector<dialogue::DialogueAct> asks = domain_.ask_acts(goal);
  const dialogue::DialogueAct& act = asks[rng.uniform_index(asks.size())];
  return {act.to_string(), nlg_.realise(false, {act}, rng)};
}

}  // namespace ari_social_sim::world_speech
