#pragma once

#include <string>
#include <vector>

namespace ari_social_sim::dialogue {

/// A user goal in the MPGT schema: owners (roles such as `patient`, `companion`; two owners make a
/// joint goal), a predicate (`go-to`, `get-info`, `eat`, `drink`, `sit`, ...) and the object path
/// the predicate applies to (`[toilet]`, `[cafe, opening_times]`, or empty for `eat()`).
struct Goal {
  std::vector<std::string> owners;
  std::string predicate;
  std::vector<std::string> object;

  /// `patient+companion` style owner text.
  std::string owner_text() const;
  /// `go-to(toilet)`, `get-info(cafe(opening_times))`, `eat()`.
  std::string predicate_text() const;
  /// Same predicate and object, whoever owns it.
  bool same_target(const Goal& other) const;
  bool is_joint() const { return owners.size() > 1; }
};

/// What an utterance does to a goal: states it (G), answers it (AG) or closes it (CG).
enum class GoalLabelKind { kStated, kAnswered, kClosed };

struct GoalLabel {
  GoalLabelKind kind{GoalLabelKind::kStated};
  Goal goal;

  /// `G(patient, go-to(toilet))`, `AG(patient+companion, eat())`, `CG(...)`.
  std::string to_string() const;
};

/// Parses MPGT goal labels separated by `;`, e.g. `G(LP+RC, go-to(lifts)); AG(RC, eat())`. Owner
/// codes are seats plus roles (LP, RP = patient; LC, RC = companion; `_` is read as `+`, one
/// corpus typo). Lenient about brackets (the corpus has a few unbalanced ones). Labels that cannot
/// be read are skipped and counted in `*skipped`.
std::vector<GoalLabel> parse_mpgt_goal_labels(const std::string& text, int* skipped = nullptr);

/// Role of an MPGT speaker or owner code: `LP`/`RP` -> patient, `LC`/`RC` -> companion, `ARI` ->
/// ARI; "" for anything else.
std::string mpgt_role(const std::string& code);

}  // namespace ari_social_sim::dialogue
