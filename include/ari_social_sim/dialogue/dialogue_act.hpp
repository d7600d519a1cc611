#pragma once

#include <string>
#include <vector>

namespace ari_social_sim::dialogue {

/// One dialogue act in the MPGT intent-slot notation (MPGT):
/// an intent, a nested slot path (outermost first) and an optional value, the innermost argument
/// of a path with at least two levels. Examples:
///   `request(location(toilet))`             -> intent request, slots [location], value toilet
///   `request(cafe(opening_times(opening_time)))` -> slots [cafe, opening_times], value
///   opening_time `request(food)`                          -> slots [food], no value `thank()` ->
///   no slots, no value
struct DialogueAct {
  std::string intent;
  std::vector<std::string> slots;
  std::string value;  ///< "" when the act has no value

  /// The MPGT notation, e.g. `request(location(toilet))`; `parse_act(to_string())` gives it back.
  std::string to_string() const;
  /// Slots and value as one path: [location, toilet].
  std::vector<std::string> path() const;
  /// Builds an act from an intent and a full path; the innermost of >= 2 names becomes the value.
  static DialogueAct from_path(std::string intent, std::vector<std::string> path);

  bool operator==(const DialogueAct& other) const;
  bool operator!=(const DialogueAct& other) const { return !(*this == other); }
};

/// The 24 intents annotated in MPGT, in that order.
const std::vector<std::string>& mpgt_intents();
/// True when `intent` is one of mpgt_intents().
bool is_known_intent(const std::string& intent);

/// Parses one act, e.g. `request(location(toilet))`. Strict: names are [a-z0-9_-]+, brackets must
/// balance and every act ends with `()` or a path. Throws core::ConfigError naming `source` and the
/// text when malformed or when the intent is not an MPGT intent.
DialogueAct parse_act(const std::string& text, const std::string& source);

/// Parses an act pattern: an act in which `*` may stand for a name (`request(location(*))`); the
/// names `*` replaces come back as "*". Errors quote the pattern as written. Throws like parse_act.
DialogueAct parse_pattern(const std::string& text, const std::string& source);

/// Parses acts separated by `;` or `,` at bracket depth 0 (both separators occur in MPGT).
/// Lenient mode (`repair` true) is for the corpus: it drops surplus closing brackets and closes
/// unclosed ones, counting each repair in `*repairs`; intents need not be known.
std::vector<DialogueAct> parse_acts(const std::string& text, const std::string& source,
                                    bool repair = false, int* repairs = nullptr);

/// Parses a bare slot path such as `cafe(opening_times)` into [cafe, opening_times]; "" gives an
/// empty path. Throws core::ConfigError naming `source` when malformed.
std::vector<std::string> parse_path(const std::string& text, const std::string& source);

/// Acts joined the MPGT way: `greet(); inform(ari(name))`.
std::string acts_to_string(const std::vector<DialogueAct>& acts);

}  // namespace ari_social_sim::dialogue
