#include "bezcam/error.hpp"

namespace bezcam {

namespace {
std::string compose(const std::string& where, const std::string& what) {
  return where.empty() ? what : where + ": " + what;
}
void add(std::string& out, const std::string& part) {
  if (part.empty()) return;
  if (!out.empty()) out += ": ";
  out += part;
}
}  // namespace

std::string Place::to_string() const {
  std::string out;
  if (option)
    add(out, *option);
  else if (setting)
    add(out, *setting);
  if (file) add(out, *file);
  if (json_path) add(out, *json_path);
  if (line)
    add(out, "line " + std::to_string(*line) + (column ? ", column " + std::to_string(*column) : std::string()));
  if (reg) add(out, *reg);
  return out;
}

std::string Place::relative_path() const { return json_path.value_or(std::string()); }

Place Place::in_json(std::string file, const std::string& prefix, const std::string& rest) {
  Place p;
  p.file = std::move(file);
  p.json_path = prefix.empty() ? rest : rest.empty() ? prefix : prefix + "." + rest;
  return p;
}

Error::Error(ErrorFamily family, ErrorId id, Place where, std::string what)
    : std::runtime_error(compose(where.to_string(), what)),
      family_(family),
      id_(id.str()),
      place_(std::move(where)),
      where_(place_.to_string()),
      message_(std::move(what)) {}

Error Error::with_option(std::string opt) const {
  Place p = place_;
  p.option = std::move(opt);
  p.setting.reset();
  Error e(family_, ErrorId(id_), std::move(p), message_);
  e.more_ = more_;
  return e;
}

}  // namespace bezcam
