#include "python/options_binding.h"

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "options/option_check.h"
#include "options/option_parser.h"
#include "options/stereo_options.h"

namespace py = pybind11;

namespace msp {
namespace python {
namespace {

// The attribute of an option: its name without the section
// ("PatchMatchStereo.window_radius" -> "window_radius").
std::string AttributeName(const std::string& option_name) {
  return option_name.substr(option_name.rfind('.') + 1);
}

// The attributes of a struct and their help texts, in usage order.
class FieldList : public OptionVisitor {
 public:
  void Visit(const std::string& name, int*, const std::string& help, OptionGroup) override {
    Add(name, help);
  }
  void Visit(const std::string& name, double*, const std::string& help, OptionGroup) override {
    Add(name, help);
  }
  void Visit(const std::string& name, bool*, const std::string& help, OptionGroup) override {
    Add(name, help);
  }
  void Visit(const std::string& name, std::string*, const std::string& help, OptionGroup) override {
    Add(name, help);
  }

  std::vector<std::pair<std::string, std::string>> fields;  // attribute, help

 private:
  void Add(const std::string& name, const std::string& help) {
    fields.emplace_back(AttributeName(name), help);
  }
};

// Reads or writes the field of one attribute, found by the parser's list of
// the struct's options, so that no option is listed twice.
class FieldAccess : public OptionVisitor {
 public:
  // Reads the attribute into value(), or with `new_value` writes it.
  FieldAccess(std::string attribute, py::handle new_value = py::handle())
      : attribute_(std::move(attribute)), new_value_(new_value) {}

  void Visit(const std::string& name, int* field, const std::string&, OptionGroup) override {
    Access(name, field, "an int");
  }
  void Visit(const std::string& name, double* field, const std::string&, OptionGroup) override {
    Access(name, field, "a float");
  }
  void Visit(const std::string& name, bool* field, const std::string&, OptionGroup) override {
    Access(name, field, "a bool");
  }
  void Visit(const std::string& name, std::string* field, const std::string&,
             OptionGroup) override {
    Access(name, field, "a str");
  }

  bool found() const { return found_; }
  const py::object& value() const { return value_; }

 private:
  template <typename T>
  void Access(const std::string& name, T* field, const char* type) {
    if (found_ || AttributeName(name) != attribute_) return;
    found_ = true;
    if (!new_value_) {
      value_ = py::cast(*field);
      return;
    }
    // A bool takes True or False only (numpy's too), not any object with a
    // truth value; an int no float; a float an int as well.
    py::detail::make_caster<T> caster;
    if (!caster.load(new_value_, /*convert=*/!std::is_same<T, bool>::value)) {
      throw py::type_error(attribute_ + " takes " + type + ", not " +
                           py::type::handle_of(new_value_).attr("__name__").cast<std::string>());
    }
    *field = py::detail::cast_op<T>(std::move(caster));
  }

  std::string attribute_;
  py::handle new_value_;
  bool found_ = false;
  py::object value_;
};

// Binds one options struct as class `name`: `visit` is the parser's list of
// its fields (option_parser.h), `check` the command's Check() of it.
template <typename Options>
void BindOptionsClass(py::module_& module, const char* name, const char* doc,
                      void (*visit)(Options*, OptionVisitor*), void (*check)(const Options&)) {
  // The attribute's value, or with `new_value` sets it; false when the struct
  // has no such attribute.
  auto access = [visit](const Options& options, const std::string& attribute, py::handle new_value,
                        py::object* value) {
    FieldAccess field(attribute, new_value);
    // Reading visits the fields without writing them.
    visit(const_cast<Options*>(&options), &field);
    if (value != nullptr) *value = field.value();
    return field.found();
  };
  auto get = [access](const Options& options, const std::string& attribute) {
    py::object value;
    access(options, attribute, py::handle(), &value);
    return value;
  };
  // Sets the options named in `values` (kwargs or a pickled state).
  const std::string class_name = name;
  auto set_all = [access, class_name](Options* options, const py::dict& values) {
    for (const auto& item : values) {
      const std::string attribute = py::str(item.first);
      if (!access(*options, attribute, item.second, nullptr)) {
        throw py::type_error(class_name + " has no option `" + attribute + "`");
      }
    }
  };
  FieldList list;
  Options defaults;
  visit(&defaults, &list);
  const std::vector<std::pair<std::string, std::string>> fields = list.fields;
  auto to_dict = [fields, get](const Options& options) {
    py::dict dict;
    for (const auto& field : fields) dict[py::str(field.first)] = get(options, field.first);
    return dict;
  };

  py::class_<Options> cls(module, name, doc);
  cls.def(py::init([set_all](const py::kwargs& kwargs) {
            Options options;
            set_all(&options, kwargs);
            return options;
          }),
          "The defaults, but for the options given by name.");
  for (const auto& field : fields) {
    const std::string attribute = field.first;
    cls.def_property(
        attribute.c_str(),
        [get, attribute](const Options& options) { return get(options, attribute); },
        [access, attribute](Options& options, py::handle value) {
          access(options, attribute, value, nullptr);
        },
        field.second.c_str());
  }
  cls.def("todict", to_dict, "The options as a dict, attribute -> value.");
  cls.def(
      "check", [check](const Options& options) { check(options); },
      "Raises OptionError (a ValueError) naming the first invalid option, as msp_stereo does.");
  cls.def("__repr__", [class_name, to_dict](const Options& options) {
    std::string text = class_name + "(";
    const char* separator = "";
    for (const auto& item : to_dict(options)) {
      text +=
          separator + std::string(py::str(item.first)) + "=" + std::string(py::repr(item.second));
      separator = ", ";
    }
    return text + ")";
  });
  cls.def("__eq__", [to_dict](const Options& options, const py::object& other) -> py::object {
    if (!py::isinstance<Options>(other))
      return py::reinterpret_borrow<py::object>(Py_NotImplemented);
    return py::bool_(to_dict(options).equal(to_dict(other.template cast<const Options&>())));
  });
  cls.def("__copy__", [](const Options& options) { return Options(options); });
  cls.def("__deepcopy__", [](const Options& options, const py::dict&) { return Options(options); });
  cls.def(py::pickle(to_dict, [set_all](const py::dict& state) {
    Options options;
    set_all(&options, state);
    return options;
  }));
}

}  // namespace

void BindOptions(py::module_& module) {
  BindOptionsClass<PatchMatchStereoOptions>(
      module, "PatchMatchOptions",
      "The --PatchMatchStereo.* options: pycolmap's PatchMatchOptions, field by field with "
      "COLMAP's names and defaults. The README says which are honoured, mapped or ignored.",
      &VisitPatchMatchStereoOptions, &CheckPatchMatchStereoOptions);
  BindOptionsClass<MspStereoOptions>(module, "MspStereoOptions",
                                     "The --MspStereo.* options: this project's own.",
                                     &VisitMspStereoOptions, &CheckMspStereoOptions);
}

}  // namespace python
}  // namespace msp
