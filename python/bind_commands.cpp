// The commands on clips: read_clip, write_clip, resample, evaluate.
#include "common.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/clip/rate_value.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/clip/resample_loop.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/eval/error_row.h"
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/source_motion.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"
#include "rotinterp/io/files/file_errors.h"

#include <cerrno>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp::python {
namespace {

namespace fs = std::filesystem;

// ---- files ------------------------------------------------------------------------

// The reader's error as a Python exception: OSError subclasses for what the file
// system says (its kind), ValueError for a file that is not a clip.
[[noreturn]] void raise_read_error(const Error& e, const fs::path& path) {
  PyObject* type = PyExc_ValueError;
  int err = 0;
  // An if chain, not a switch: ErrorKind is open, so its kinds are no enumerators.
  if (e.kind == file_error::no_file) type = PyExc_FileNotFoundError, err = ENOENT;
  else if (e.kind == file_error::directory) type = PyExc_IsADirectoryError, err = EISDIR;
  else if (e.kind == file_error::cannot_open) type = PyExc_OSError, err = EIO;
  else value_error(e.message);
  PyErr_SetObject(type, py::make_tuple(err, e.message, path.string()).ptr());
  throw py::error_already_set();
}

void write_path(const Clip& clip, const fs::path& path, const std::string& bvh_order) {
  if (!can_write_format(path))
    value_error("output '" + path.string() + "': unknown format (use " + format_names(writable, " or ", true) + ")");
  WriteOptions o;
  o.bvh_order = bvh_order;
  Status s = Ok{};
  {
    py::gil_scoped_release release;
    s = write_clip(clip, path, o);
  }
  if (!s) {
    PyErr_SetString(PyExc_OSError, s.error().c_str());
    throw py::error_already_set();
  }
}

// ---- resample ------------------------------------------------------------------------

Rate rate_of(const py::handle& fps) {
  // Fractions print as "30000/1001", numbers and strings as themselves; read as --fps reads them.
  return checked(parse_rate_value("fps", py::str(fps).cast<std::string>()));
}

Clip resample(const Clip& clip, const py::object& fps, const py::object& keep_every, const std::string& method,
              const std::map<std::string, std::string>& method_for, const std::string& translation,
              const py::object& range, const py::object& loop) {
  ResampleOptions o;
  if (!fps.is_none()) o.fps = rate_of(fps);
  if (!keep_every.is_none()) {
    o.keep_every = static_cast<std::size_t>(whole_number(keep_every, "keep_every", 1, kMaxKeepEvery));
  }
  o.method = method_of(method).name;
  for (const auto& [joint, m] : method_for) o.method_for.emplace_back(joint, method_of(m).name);
  o.translation = checked(parse_translation_interp(translation));
  if (!range.is_none()) {
    const auto r = range.cast<std::pair<std::optional<double>, std::optional<double>>>();
    for (const std::optional<double>& end : {r.first, r.second})
      if (end && !std::isfinite(*end)) value_error("range has a non-finite value: " + std::to_string(*end));
    TimeRange tr;
    if (r.first) tr.start = *r.first;
    if (r.second) tr.end = *r.second;
    o.range = tr;
  }
  // loop: None/False off; True or "auto" detects the form; "closed" or "open" forces it (resample --loop).
  std::optional<std::optional<LoopForm>> cycle;
  if (py::isinstance<py::bool_>(loop)) {
    if (loop.cast<bool>()) cycle.emplace();
  } else if (py::isinstance<py::str>(loop)) {
    cycle = checked(parse_loop_form(loop.cast<std::string>()));
  } else if (!loop.is_none()) {
    throw py::type_error("loop must be None, a bool, 'auto', 'closed' or 'open', got " + py::repr(loop).cast<std::string>());
  }
  Result<Clip> out = make_error("");
  {
    py::gil_scoped_release release;
    if (cycle) {
      auto looped = resample_cycle(clip, o, *cycle);
      out = looped ? Result<Clip>(std::move(looped->clip)) : Result<Clip>(looped.failure());
    } else {
      out = resample_clip(clip, o);
    }
  }
  return checked(std::move(out));
}

// ---- evaluate --------------------------------------------------------------------------

py::dict evaluate(const py::object& inputs, const std::optional<std::vector<std::string>>& method_names_in,
                  const py::object& keep_every, int subframe, const py::object& shell_distance,
                  const py::object& metrics) {
  ClipEvalOptions o;
  // As eval --metrics takes them: "angle,fk", or a list of names; None is all.
  if (!metrics.is_none()) {
    std::string list;
    if (py::isinstance<py::str>(metrics)) {
      list = metrics.cast<std::string>();
    } else {
      for (const py::handle name : metrics) list += (list.empty() ? "" : ",") + py::str(name).cast<std::string>();
    }
    const Result<MetricSet> chosen = parse_metrics(list);
    if (!chosen) value_error("metrics: " + chosen.error());
    o.metrics = *chosen;
  }
  if (method_names_in) {
    o.methods = *method_names_in;
  } else {
    for (const MethodInfo& m : methods()) o.methods.push_back(m.name);
  }
  for (std::string& m : o.methods) {
    m = method_of(m).name;  // one spelling in the results ("SLERP" is slerp)
  }
  for (const py::handle n : keep_every) {
    o.keep_every.push_back(static_cast<int>(whole_number(n, "keep_every values", 1, kMaxKeepEvery)));
  }
  o.subframe = subframe;
  // A length as eval --shell-distance takes it ("3cm"), or a number of metres; its parser's refusals.
  const Result<double> shell = parse_length(py::str(shell_distance).cast<std::string>());
  if (!shell) value_error("shell_distance: " + shell.error());
  o.shell_distance_m = *shell;
  // One clip, one path, or a list of them; paths keep their text as the clip id (as
  // in errors.csv), clips their name.
  std::vector<py::object> items;
  if (py::isinstance<py::list>(inputs) || py::isinstance<py::tuple>(inputs)) {
    for (const auto& h : inputs) items.push_back(py::reinterpret_borrow<py::object>(h));
  } else {
    items.push_back(inputs);
  }
  std::vector<ErrorRow> rows;
  for (const py::object& item : items) {
    Clip clip;
    std::string id;
    if (py::isinstance<Clip>(item)) {
      clip = item.cast<Clip>();
      id = clip.name;
    } else {
      id = py::str(item).cast<std::string>();
      clip = read_path(id, py::none());
    }
    Result<std::vector<ErrorRow>> r = make_error("");
    {
      py::gil_scoped_release release;
      r = evaluate_clip(clip, id, o);
    }
    std::vector<ErrorRow> part = checked(std::move(r));
    rows.insert(rows.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
  }
  // Columns, named and ordered as in errors.csv (error_row.h). End Site rows have no
  // rotation or smoothness values, rows of joints that are not feet no foot-contact
  // values: NaN there, as pandas reads the CSV's empty cells.
  const std::size_t n = rows.size();
  py::list clip, method, joint, kind, unit;
  py::array_t<long long> keep(n), frames(n), samples(n);
  const std::vector<ErrorValueColumn>& measured = error_value_columns();
  std::vector<py::array_t<double>> values;
  for (std::size_t c = 0; c < measured.size(); ++c) values.emplace_back(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ErrorRow& r = rows[i];
    clip.append(r.clip);
    method.append(r.method);
    joint.append(r.joint);
    kind.append(r.end_site ? "end_site" : "joint");
    unit.append(r.unit);
    keep.mutable_at(i) = r.keep_every;
    frames.mutable_at(i) = static_cast<long long>(r.frames);
    samples.mutable_at(i) = static_cast<long long>(r.samples);
    for (std::size_t c = 0; c < measured.size(); ++c)
      values[c].mutable_at(i) =
          (r.end_site && measured[c].joint_only) || (!r.foot && measured[c].foot_only) ? std::nan("") : r.*measured[c].field;
  }
  py::module_ np = py::module_::import("numpy");
  std::map<std::string, py::object> by_name = {
      {"clip", np.attr("array")(clip, "str")},     {"method", np.attr("array")(method, "str")},
      {"keep_every", keep},                         {"joint", np.attr("array")(joint, "str")},
      {"frames", frames},                           {"samples", samples},
      {"kind", np.attr("array")(kind, "str")},     {"unit", np.attr("array")(unit, "str")}};
  for (std::size_t c = 0; c < measured.size(); ++c) by_name.emplace(measured[c].name, values[c]);
  py::dict out;
  for (const std::string& name : error_csv_schema(csv_metrics(o.metrics, false)).columns())
    out[py::str(name)] = by_name.at(name);
  return out;
}

}  // namespace

// The reading options of read_clip and info: the animation and the unit, in the
// forms --anim and --unit take (a number is metres per unit), and
// --allow-external-files.
ReadOptions read_options(const py::object& anim, const py::object& unit, bool allow_external_files = false) {
  ReadOptions o;
  o.allow_external_files = allow_external_files;
  if (!anim.is_none()) o.animation = py::str(anim).cast<std::string>();
  if (!unit.is_none()) o.unit = metres_per_unit_arg(unit, "unit");
  return o;
}

Clip read_path(const std::string& path, const py::object& anim, const py::object& unit, bool allow_external_files) {
  const ReadOptions o = read_options(anim, unit, allow_external_files);
  Result<Clip> c = make_error("");
  {
    py::gil_scoped_release release;
    c = read_clip(path, o);
  }
  if (!c) raise_read_error(c.failure(), path);
  return std::move(*c);
}

// rotinterp.info: the document `rotinterp info --json` prints (clip_info_json), as
// Python data. Warnings go into its "warnings", not to stderr.
py::object info(const std::string& path, const py::object& anim, const py::object& unit, bool allow_external_files) {
  ReadOptions o = read_options(anim, unit, allow_external_files);
  o.on_warning = [](const std::string&) {};
  std::string text;
  Result<ClipFileInfo> r = make_error("");
  {
    py::gil_scoped_release release;
    r = reading_or_failure(inspect_clip_for_info(path, o));
    if (r) text = clip_info_json(path, *r);
  }
  if (!r) raise_read_error(r.failure(), path);
  return py::module_::import("json").attr("loads")(text);
}

Clip read_path_with_source_motion(const std::string& path, SourceMotion& motion) {
  const ReadOptions options = read_options(py::none(), py::none());
  Result<Clip> c = make_error("");
  {
    py::gil_scoped_release release;
    c = read_clip_with_source_motion(path, options, motion);
  }
  if (!c) raise_read_error(c.failure(), path);
  return std::move(*c);
}

Clip clip_or_path(const py::object& input) {
  if (py::isinstance<Clip>(input)) return input.cast<Clip>();
  return read_path(py::str(input).cast<std::string>(), py::none());
}

void bind_commands(py::module_& m) {
  m.def("read_clip", &read_path, py::arg("path"), py::arg("anim") = py::none(), py::arg("unit") = py::none(),
        py::kw_only(), py::arg("allow_external_files") = false);
  m.def("info", &info, py::arg("path"), py::arg("anim") = py::none(), py::arg("unit") = py::none(), py::kw_only(),
        py::arg("allow_external_files") = false);
  m.def("write_clip", &write_path, py::arg("clip"), py::arg("path"), py::arg("bvh_order") = "ZXY");
  m.def("resample", &resample, py::arg("clip"), py::arg("fps") = py::none(), py::arg("keep_every") = py::none(),
        py::arg("method") = std::string(kDefaultResampleMethod),
        py::arg("method_for") = std::map<std::string, std::string>{}, py::arg("translation") = "cubic",
        py::arg("range") = py::none(), py::arg("loop") = py::none());
  m.def("evaluate", &evaluate, py::arg("inputs"), py::arg("methods") = py::none(),
        py::arg("keep_every") = py::make_tuple(2, 4, 8, 16), py::arg("subframe") = 0,
        py::arg("shell_distance") = py::float_(kDefaultShellDistanceMetres), py::arg("metrics") = py::none());
}

}  // namespace rotinterp::python
