#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/DialogueInfo.h"
#include "ari_social_sim/DialogueObservation.h"
#include "ari_social_sim/DialogueOutcome.h"
#include "ari_social_sim/DialoguePerception.h"
#include "ari_social_sim/DialogueUtterance.h"
#include "ari_social_sim/dialogue/dialogue_env.hpp"
#include "ari_social_sim/dialogue/spoken_dialogue.hpp"

namespace ari_social_sim::nodes {

/// Acts in MPGT notation, one string each.
std::vector<std::string> to_strings(const std::vector<dialogue::DialogueAct>& acts);
/// Goal labels as `G(owner, predicate)` strings.
std::vector<std::string> to_strings(const std::vector<dialogue::GoalLabel>& goals);

DialoguePerception to_msg(const dialogue::Perception& heard);
/// Its inverse; throws core::RequestError on a malformed or unknown act.
dialogue::Perception from_msg(const DialoguePerception& msg);
DialogueObservation to_msg(const dialogue::Observation& observation);
/// `roles`: the humans' roles, the order of info.patience.
DialogueInfo to_msg(const dialogue::StepInfo& info, const std::vector<std::string>& roles);
/// An utterance as it starts playing (/sim/dialogue/utterances): the event gives the dialogue,
/// the stamp and the speaker's world id; a human speaker also gets its person id `human<N>`.
DialogueUtterance to_msg(const dialogue::Utterance& utterance,
                         const dialogue::UtteranceEvent& event);
/// A dialogue's end (/sim/dialogue/outcome), and its inverse.
DialogueOutcome to_msg(const dialogue::OutcomeEvent& outcome);
dialogue::OutcomeEvent from_msg(const DialogueOutcome& msg);

/// Acts from MPGT strings; throws core::RequestError naming `field[i]` on a malformed act or an
/// unknown intent.
std::vector<dialogue::DialogueAct> acts_from_msg(const std::vector<std::string>& acts,
                                                 const std::string& field);

}  // namespace ari_social_sim::nodes
