#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/DialogueInfo.h"
#include "ari_social_sim/DialogueObservation.h"
#include "ari_social_sim/DialoguePerception.h"
#include "ari_social_sim/DialogueUtterance.h"
#include "ari_social_sim/dialogue/dialogue_env.hpp"

namespace ari_social_sim::nodes {

/// Acts in MPGT notation, one string each.
std::vector<std::string> to_strings(const std::vector<dialogue::DialogueAct>& acts);
/// Goal labels as `G(owner, predicate)` strings.
std::vector<std::string> to_strings(const std::vector<dialogue::GoalLabel>& goals);

DialoguePerception to_msg(const dialogue::Perception& heard);
DialogueObservation to_msg(const dialogue::Observation& observation);
/// `roles`: the humans' roles, the order of info.patience.
DialogueInfo to_msg(const dialogue::StepInfo& info, const std::vector<std::string>& roles);
/// An utterance of dialogue `dialogue`, stamped `stamp_s`; speaker ids and person id are the
/// caller's to fill.
DialogueUtterance to_msg(const dialogue::Utterance& utterance, uint32_t dialogue, double stamp_s);

/// Acts from MPGT strings; throws core::RequestError naming `field[i]` on a malformed act or an
/// unknown intent.
std::vector<dialogue::DialogueAct> acts_from_msg(const std::vector<std::string>& acts,
                                                 const std::string& field);

}  // namespace ari_social_sim::nodes
