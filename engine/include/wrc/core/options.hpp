// Named options as the engine reads them, whoever supplies them: a Lua table (the binding converts it), a C
// string "key=value key2=value2" (the C API), or C++ code building them. One reader checks every key, type and
// range and names what is wrong: the same message from every front end, types in its words (OptionDialect).
#pragma once

#include "wrc/core/error.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wrc {

struct OptionTable;

// The words of the front end that built an option tree, for messages about option types: a Python user passes a
// dict where Lua takes a table, a MATLAB user a struct, a C API user dotted keys. The front end sets its dialect on
// the tables it builds (OptionTable::dialect); a reader of a nested table keeps its parent reader's, so that a table
// C++ code put into a front end's options speaks the front end's words too. The default is Lua's, the
// language the options are documented in (and the words of C++ code building options).
enum class OptionDialect { lua, c, python, matlab };

struct OptionWords {
  // A value's type, as a message names what it got ("got list"); a number is "number" in every dialect.
  const char* boolean;
  const char* string;
  const char* array;
  const char* table;
  // What a message asks for: a nested table ("a dict"), an array of numbers, of strings, and a range of numbers.
  const char* a_table;
  const char* numbers;
  const char* strings;
  const char* range;
};
const OptionWords& option_words(OptionDialect dialect);

// One value: a number, a boolean, a string, an array (of values), a table (named values) or an engine object
// (e.g. a profile) with the name of its type.
struct OptionValue {
  enum class Type { number, boolean, string, array, table, object };
  Type type = Type::number;
  double number = 0;
  bool boolean = false;
  std::string string;                    // the string, or the object's type name ("wrc.Profile")
  std::vector<OptionValue> array;
  std::shared_ptr<const OptionTable> table;
  std::shared_ptr<const void> object;

  static OptionValue of(double v);
  static OptionValue of(bool v);
  static OptionValue of(std::string v);
  static OptionValue of(std::vector<OptionValue> v);
  static OptionValue of(OptionTable t);
  static OptionValue of_object(std::shared_ptr<const void> p, std::string type);
  // "number", the dialect's word for a boolean, string, array or table, or the object's type ("wrc.Profile").
  const char* type_name(OptionDialect dialect) const;
};

// Named values in the order given.
struct OptionTable {
  std::vector<std::pair<std::string, OptionValue>> entries;
  OptionDialect dialect = OptionDialect::lua;  // of the front end that built it
  const OptionValue* find(std::string_view key) const;
  OptionTable& set(std::string key, OptionValue v);  // replaces an entry of the same key
  bool empty() const { return entries.empty(); }
};

// Bounds of option input, whoever supplies it: tables nest at most kMaxOptionDepth levels (a dotted key has at most
// that many names; a Lua table as deep), a key of an option text has at most kMaxOptionKeyLength characters and the
// text at most kMaxOptionTextLength bytes (a million numbers of a list fit).
inline constexpr int kMaxOptionDepth = 16;
inline constexpr std::size_t kMaxOptionKeyLength = 256;
inline constexpr std::size_t kMaxOptionTextLength = std::size_t{32} << 20;

// Parses "key=value key2=value2" (blanks or ';' between pairs; a value is a number, true/false, a list of numbers
// "a,b,c", or a string; dotted keys "shift.y=1e-3" make nested tables), in time linear in the text. A key given
// twice, a name that is both a value and a table, an empty name ("a..b") and input past the bounds above are errors
// that name `context` and the key. The table's dialect is `dialect`: the C API's, or MATLAB's, whose name/value pairs
// and structs its gateway passes as this text.
OptionTable parse_option_text(std::string_view text, std::string_view context,
                              OptionDialect dialect = OptionDialect::c);

// What a key means, beside its name and the default its options struct holds: the unit ("m", "N", "Pa", "rad",
// "m/s"; "-" for pure numbers, strings, booleans and tables) and one line of help. Readers pass it with every
// key, so that the one reading function is also the description that help texts and docs/reference are made from.
struct OptionDoc {
  const char* unit = "";
  const char* help = "";
};

// One key as a documenting reader saw it (OptionReader::documenting).
struct OptionInfo {
  std::string key;        // "radius"; a nested table's keys with its name in front ("creepage.xi")
  std::string type;       // "number", "integer", "boolean", "string", "choice", "numbers", "strings", "list",
                          // "table" or an engine object's type ("wrc.Profile")
  std::string unit, help;
  std::string fallback;   // the default as text ("0.45", "true", "\"accurate\""); "" when there is none
  bool required = false;
  std::vector<std::string> choices;  // of a "choice"
};

// Reads an OptionTable, remembering which keys were asked for; finish() rejects the others, naming the closest
// known key (a typo such as 'raduis' for 'radius'). Every getter checks the type and that numbers are finite.
//
// Getters come in three forms: `number(key, doc)` (nullopt when absent), `number(key, doc, fallback)` (the
// fallback when absent: the options struct's member, the one place defaults live) and `need_number(key, doc)`
// (required). The forms without a doc are kept for keys not yet documented.
//
// A documenting reader (documenting()) reads an empty table and records every key a reading function asks for,
// with its type, unit, help, default and choices, instead of reading it: required getters then return a
// placeholder (0, "", an empty list) and finish() does nothing. A reading function that checks what it read must skip
// its checks while documenting() (validation belongs in the options struct's validate(), which a documenting pass
// never calls).
class OptionReader {
 public:
  OptionReader(const OptionTable& table, std::string context);
  // A reader of nothing that records into `out` (keys in the order asked, each once).
  static OptionReader documenting(std::string context, std::vector<OptionInfo>& out);
  bool documenting() const { return doc_ != nullptr; }
  const std::string& context() const { return context_; }
  // The words of the front end that built the options (OptionDialect), for messages.
  const OptionWords& words() const { return option_words(dialect_); }
  const char* type_name(const OptionValue& v) const { return v.type_name(dialect_); }
  bool has(std::string_view key);  // present (and counted as known)
  const OptionValue* value(std::string_view key);  // nullptr when absent
  // value() of a key that its reader checks itself (e.g. one of several types): a documenting reader records it with
  // `type` ("number or string"), its doc and the default as text.
  const OptionValue* value(std::string_view key, std::string_view type, OptionDoc doc, std::string fallback = {});

  std::optional<double> number(std::string_view key, OptionDoc doc = {});
  double number(std::string_view key, OptionDoc doc, double fallback);
  double number(std::string_view key, double fallback) { return number(key, OptionDoc{}, fallback); }
  double need_number(std::string_view key, OptionDoc doc = {});
  // A whole number in [lo, hi].
  std::optional<int> integer(std::string_view key, int lo, int hi, OptionDoc doc = {});
  int integer(std::string_view key, int lo, int hi, OptionDoc doc, int fallback);
  std::optional<bool> boolean(std::string_view key, OptionDoc doc = {});
  bool boolean(std::string_view key, OptionDoc doc, bool fallback);
  std::optional<std::string> string(std::string_view key, OptionDoc doc = {});
  std::string string(std::string_view key, OptionDoc doc, std::string fallback);
  // One of `choices`; the message lists them.
  std::optional<std::string> choice(std::string_view key, std::initializer_list<std::string_view> choices,
                                    OptionDoc doc = {});
  std::string choice(std::string_view key, std::initializer_list<std::string_view> choices, OptionDoc doc,
                     std::string fallback);
  // An array of finite numbers (a single number counts as an array of one). With finite = false, NaN and
  // infinities are kept (for the caller to report with more context).
  std::optional<std::vector<double>> numbers(std::string_view key, bool finite = true);
  std::optional<std::vector<double>> numbers(std::string_view key, OptionDoc doc, bool finite = true);
  // An array of strings.
  std::optional<std::vector<std::string>> strings(std::string_view key, OptionDoc doc = {});
  // A list of numbers: an array, a single number, or a table {from =, to =, step =} (inclusive; the step's sign
  // follows from and to). At most max_count values.
  std::optional<std::vector<double>> number_list(std::string_view key, std::size_t max_count = 1000000);
  std::optional<std::vector<double>> number_list(std::string_view key, OptionDoc doc, std::size_t max_count = 1000000);
  // A nested table (nullopt when absent); its reader's context is "<context>: <key>". A documenting reader returns a
  // documenting reader of the table, whose keys it records as "<key>.<name>".
  std::optional<OptionReader> table(std::string_view key, OptionDoc doc = {});
  // An engine object of the given type name.
  std::shared_ptr<const void> object(std::string_view key, std::string_view type, OptionDoc doc = {});

  // Declares keys as known without reading them (handled elsewhere, e.g. by the binding).
  void allow(std::initializer_list<std::string_view> keys);
  // The entries never asked for, in the order given (options passed on to someone else, e.g. a reader plugin).
  std::vector<const std::pair<std::string, OptionValue>*> rest() const;
  // Throws for a key that was never asked for: "<context>: unknown key 'raduis' (did you mean 'radius'?
  // expected one of: ...)". A nested reader (table()) is finished by whoever reads it.
  void finish() const;

 private:
  // "<context>: '<key>' must be <expected>, got <type>", then " (<key>: <help>)" when a help is given.
  [[noreturn]] void type_error(std::string_view key, const OptionValue& v, std::string_view expected,
                               std::string_view help = {}) const;
  // While documenting: records the key (once; a later call fills what an earlier one left empty).
  void note(std::string_view key, std::string_view type, OptionDoc doc, std::string fallback = {},
            bool required = false, std::vector<std::string> choices = {});
  // A reader of a table nested in this one's: the same dialect.
  OptionReader nested(const OptionTable& table, std::string context) const;
  const OptionTable& table_;
  std::string context_;
  OptionDialect dialect_;
  std::vector<std::string> known_;
  std::vector<OptionInfo>* doc_ = nullptr;  // documenting: where keys are recorded
  std::string prefix_;                      // documenting a nested table: "<key>."
};

// The entry of `known` closest to `key` by edit distance, or "" when none is plausibly a typo of it.
std::string closest_name(std::string_view key, const std::vector<std::string>& known);

}  // namespace wrc
