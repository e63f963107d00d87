// The pocket keys (docs/pocket.md): `operation`, `region`, `pattern`,
// `angle`, `stepover`, `load`, `finish`, `entry`, `rest_from`; the drilling keys
// (docs/holes.md): `to`, `peck`, `chip_break`, `dwell`, `retract_z`.
#include <cmath>

#include "bezcam/format.hpp"
#include "job_json_detail.hpp"

namespace bezcam {

PocketKeys PocketKeys::over(const PocketKeys& base) const {
  PocketKeys r = base;
  if (operation) r.operation = operation;
  if (region) r.region = region;
  if (pattern) r.pattern = pattern;
  if (angle) r.angle = angle;
  if (stepover) r.stepover = stepover;
  if (finish_stock) r.finish_stock = finish_stock;
  if (rest_from) r.rest_from = rest_from;
  if (load) r.load = load;
  if (entry) r.entry = entry;
  return r;
}

DrillKeys DrillKeys::over(const DrillKeys& base) const {
  DrillKeys r = base;
  if (to_tip) r.to_tip = to_tip;
  if (peck) r.peck = peck;
  if (chip_break) r.chip_break = chip_break;
  if (dwell) r.dwell = dwell;
  if (retract_z) r.retract_z = retract_z;
  return r;
}

namespace detail {

namespace {

double entry_angle(const JsonCtx& ctx, const json& obj, const std::string& kp) {
  if (!obj.contains("angle")) return 3;
  const double a = ctx.positive(obj["angle"], kp + ".angle");
  if (a >= 90) ctx.fail(kp + ".angle", errc::job_range, "expected an angle below 90 degrees, found " + fmt_num(a));
  return a;
}

PocketEntry parse_entry(const JsonCtx& ctx, const json& v, const std::string& kp) {
  PocketEntry e;
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "helix") return e;
    if (s == "ramp") {
      e.kind = PocketEntry::Kind::ramp;
      return e;
    }
    if (s == "plunge") {
      e.kind = PocketEntry::Kind::plunge;
      return e;
    }
    ctx.fail(kp, errc::job_pocket, "expected \"helix\", \"ramp\" or \"plunge\", found " + describe(v));
  }
  if (!v.is_object() || v.size() != 1)
    ctx.expected(
        kp, "\"helix\", \"ramp\", \"plunge\", {\"helix\": {\"radius\": R, \"angle\": A}} or {\"ramp\": {\"angle\": A}}",
        v);
  const std::string kind = v.begin().key();
  const json& o = v.begin().value();
  const std::string sp = kp + "." + kind;
  if (kind != "helix" && kind != "ramp") ctx.check_keys(v, kp, {"helix", "ramp"});
  if (!o.is_object()) ctx.expected(sp, "an object", o);
  if (kind == "helix") {
    ctx.check_keys(o, sp, {"radius", "angle"});
    if (o.contains("radius")) e.radius = ctx.positive(o["radius"], sp + ".radius");
  } else {
    e.kind = PocketEntry::Kind::ramp;
    ctx.check_keys(o, sp, {"angle"});
  }
  e.angle = entry_angle(ctx, o, sp);
  return e;
}

}  // namespace

PocketKeys parse_pocket_keys(const JsonCtx& ctx, const json& obj, const std::string& path) {
  PocketKeys k;
  auto sub = [&](const char* key) { return path.empty() ? std::string(key) : path + "." + key; };
  if (auto it = obj.find("operation"); it != obj.end()) {
    const std::string v = ctx.string(*it, sub("operation"));
    if (v == "profile")
      k.operation = Operation::profile;
    else if (v == "pocket")
      k.operation = Operation::pocket;
    else if (v == "drill")
      k.operation = Operation::drill;
    else if (v == "bore")
      k.operation = Operation::bore;
    else
      ctx.fail(sub("operation"), errc::job_operation,
               "expected \"profile\", \"pocket\", \"drill\" or \"bore\", found " + describe(*it));
  }
  if (auto it = obj.find("region"); it != obj.end()) k.region = ctx.string(*it, sub("region"));
  if (auto it = obj.find("pattern"); it != obj.end()) {
    const std::string v = ctx.string(*it, sub("pattern"));
    if (v == "offset")
      k.pattern = PocketPattern::offset;
    else if (v == "zigzag")
      k.pattern = PocketPattern::zigzag;
    else if (v == "adaptive")
      k.pattern = PocketPattern::adaptive;
    else
      ctx.fail(sub("pattern"), errc::job_pocket,
               "expected \"offset\", \"zigzag\" or \"adaptive\", found " + describe(*it));
  }
  if (auto it = obj.find("angle"); it != obj.end()) k.angle = ctx.number(*it, sub("angle"));
  if (auto it = obj.find("stepover"); it != obj.end()) {
    const double s = ctx.number(*it, sub("stepover"));
    if (!(s > 0))
      ctx.fail(sub("stepover"), errc::job_pocket,
               "expected a stepover > 0 (the distance between neighbouring passes), found " + fmt_num(s));
    k.stepover = s;
  }
  if (auto it = obj.find("load"); it != obj.end()) {
    const double l = ctx.number(*it, sub("load"));
    if (!(l > 0))
      ctx.fail(
          sub("load"), errc::job_pocket,
          "expected a load > 0 (adaptive: the radial depth of cut, at most the tool's radius), found " + fmt_num(l));
    k.load = l;
  }
  if (auto it = obj.find("finish"); it != obj.end()) {
    const std::string kp = sub("finish");
    if (!it->is_object()) ctx.expected(kp, "an object {\"stock\": S}", *it);
    ctx.check_keys(*it, kp, {"stock"});
    k.finish_stock = ctx.positive(ctx.require(*it, kp, "stock"), kp + ".stock");
  }
  if (auto it = obj.find("entry"); it != obj.end()) k.entry = parse_entry(ctx, *it, sub("entry"));
  if (auto it = obj.find("rest_from"); it != obj.end()) k.rest_from = ctx.positive(*it, sub("rest_from"));
  return k;
}

DrillKeys parse_drill_keys(const JsonCtx& ctx, const json& obj, const std::string& path) {
  DrillKeys k;
  auto sub = [&](const char* key) { return path.empty() ? std::string(key) : path + "." + key; };
  if (auto it = obj.find("to"); it != obj.end()) {
    const std::string v = ctx.string(*it, sub("to"));
    if (v != "tip" && v != "diameter")
      ctx.fail(sub("to"), errc::job_hole,
               "expected \"diameter\" (cut_z is where the drill cuts its full diameter) or \"tip\" (cut_z is "
               "where its tip goes), found " +
                   describe(*it));
    k.to_tip = v == "tip";
  }
  auto non_negative = [&](const char* key, std::optional<double>& out, const char* what) {
    auto it = obj.find(key);
    if (it == obj.end()) return;
    const double d = ctx.number(*it, sub(key));
    if (d < 0) ctx.fail(sub(key), errc::job_hole, std::string("expected ") + what + " >= 0, found " + fmt_num(d));
    out = d;
  };
  non_negative("peck", k.peck, "a peck depth (0: no pecks)");
  non_negative("dwell", k.dwell, "a dwell in seconds");
  if (auto it = obj.find("chip_break"); it != obj.end()) k.chip_break = ctx.boolean(*it, sub("chip_break"));
  if (auto it = obj.find("retract_z"); it != obj.end()) k.retract_z = ctx.number(*it, sub("retract_z"));
  return k;
}

}  // namespace detail
}  // namespace bezcam
