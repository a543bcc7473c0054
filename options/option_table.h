// The table of msp_stereo's options: every option with its field, its help
// text and its group (OptionTable), filled in once by
// DefineStereoCommandOptions and read by the parser, the usage text and the
// start-up print (option_parser.cc). Internal to msp_options: it exposes
// Boost.Program_options, which the public headers keep out of sight.
#pragma once

#include <boost/program_options.hpp>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "options/command_line_common.h"
#include "options/option_parser.h"
#include "options/stereo_options.h"

namespace msp {

// The prefix of the advanced options' fields, and so of their names.
constexpr char kAdvancedPrefix[] = "advanced_";

// Collects option definitions into boost descriptions (used for the command
// line, the ini file and the usage text alike), one per OptionGroup, and
// remembers how to print each field's value and which option each renamed one
// became.
class OptionTable : public OptionVisitor {
 public:
  void Visit(const std::string& name, int* field, const std::string& help,
             OptionGroup group) override {
    Add(name, field, help, group);
  }
  void Visit(const std::string& name, double* field, const std::string& help,
             OptionGroup group) override {
    Add(name, field, help, group);
  }
  void Visit(const std::string& name, bool* field, const std::string& help,
             OptionGroup group) override {
    Add(name, field, help, group);
  }
  void Visit(const std::string& name, std::string* field, const std::string& help,
             OptionGroup group) override {
    Add(name, field, help, group);
  }

  // Adds `field` under `name` with its current value as the default. An
  // option of --MspStereo.advanced_* goes to the advanced group whatever
  // `group` says, and its name without the prefix, which it had before the
  // group, is remembered as renamed.
  template <typename T>
  void Add(const std::string& name, T* field, const std::string& help,
           OptionGroup group = OptionGroup::kCommon) {
    AddToGroup(name,
               boost::program_options::value<T>(field)->default_value(
                   *field, command_line::DefaultText(*field)),
               help, group);
    Remember(name, field);
  }

  // An option without a default (e.g. a required path).
  void AddNoDefault(const std::string& name, std::string* field, const std::string& help);

  // `old_name` is now `new_name`: using the old one is an error naming the new.
  void AddRenamed(const std::string& old_name, const std::string& new_name);

  // Every option, whatever its group.
  boost::program_options::options_description All() const;
  const boost::program_options::options_description& Description(OptionGroup group) const;

  const std::vector<std::string>& names() const { return names_; }
  // The current value of the index-th option's field, as ValueText gives it.
  std::string Value(size_t index) const { return values_[index](); }
  // The option `name` was renamed to, or "" when it was not.
  std::string RenamedTo(const std::string& name) const;

 private:
  void AddToGroup(const std::string& name, const boost::program_options::value_semantic* value,
                  const std::string& help, OptionGroup group);

  template <typename T>
  void Remember(const std::string& name, const T* field) {
    names_.push_back(name);
    values_.emplace_back([field] { return command_line::ValueText(*field); });
  }

  boost::program_options::options_description common_, advanced_, ignored_;
  std::vector<std::string> names_;
  std::vector<std::function<std::string()>> values_;
  std::vector<std::pair<std::string, std::string>> renamed_;
};

// Adds every option of `options` to `table`, in usage order: the top-level
// ones, COLMAP's --PatchMatchStereo.*, then --MspStereo.* (the common ones,
// then the advanced ones), and the names of renamed options.
void DefineStereoCommandOptions(StereoCommandOptions* options, OptionTable* table);

}  // namespace msp
