#include "py_sequence.h"

#include <optional>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "python_error.h"
#include "resolve/sequence_job.h"
#include "taa/error.h"

namespace py = pybind11;

namespace taa::python {
namespace {

// Keyword arguments that are not "--" + name with '_' -> '-'.
std::optional<std::string> specialFlag(const std::string& key) {
  if (key == "output") return "-o";
  if (key == "pixel_type") return "-d";
  return std::nullopt;
}

// "1-24" stays as given; an int or an iterable of ints becomes "1,2,3".
std::string framesText(const py::handle& frames) {
  if (py::isinstance<py::str>(frames)) return frames.cast<std::string>();
  if (py::isinstance<py::int_>(frames)) return std::to_string(frames.cast<int>());
  std::string text;
  for (const py::handle& frame : frames) {
    text += (text.empty() ? "" : ",") + std::to_string(frame.cast<int>());
  }
  return text;
}

// taatool's argument list for these keyword arguments, so that the options mean exactly what
// they mean on the command line (and are checked by the same code).
std::vector<std::string> commandLine(const std::string& color, const py::kwargs& kwargs,
                                     py::object& progress) {
  std::vector<std::string> args = {color};
  for (const auto& [keyHandle, value] : kwargs) {
    const std::string key = keyHandle.cast<std::string>();
    if (key == "progress") {
      progress = py::reinterpret_borrow<py::object>(value);
      continue;
    }
    if (value.is_none()) continue;
    if (key == "clip" || key == "dilate") {  // taatool has only the negative flags
      if (!value.cast<bool>()) args.push_back("--no-" + key);
      continue;
    }
    std::string flag = "--" + key;
    for (char& c : flag) c = c == '_' ? '-' : c;
    if (auto special = specialFlag(key)) flag = *special;
    if (py::isinstance<py::bool_>(value)) {
      if (value.cast<bool>()) args.push_back(flag);
    } else if (key == "frames") {
      args.insert(args.end(), {flag, framesText(value)});
    } else {
      args.insert(args.end(), {flag, py::str(value).cast<std::string>()});
    }
  }
  return args;
}

py::dict reportDict(const FrameReport& report) {
  py::dict d;
  d["index"] = report.index;
  d["count"] = report.count;
  d["frame"] = report.frame;
  d["input"] = report.inputPath;
  d["output"] = report.outputPath;
  d["history_reset"] = report.historyReset;
  d["non_finite_color_values"] = report.nonFiniteColorValues;
  return d;
}

// Thrown through the job when the progress callback raised; the Python error stays set.
struct CallbackRaised {};

py::list resolveSequence(const std::string& color, const py::kwargs& kwargs) {
  py::object progress = py::none();
  cli::CommandLine cl;
  try {
    cl = cli::parseCommandLine(commandLine(color, kwargs, progress));
    cli::resolveFrameList(cl);
  } catch (const Error& e) {
    throw PythonError(e.what());
  }

  py::list reports;
  std::vector<FrameReport> done;
  JobCallbacks callbacks;
  callbacks.frameDone = [&](const FrameReport& report) {
    done.push_back(report);
    if (progress.is_none()) return;
    py::gil_scoped_acquire gil;
    try {
      progress(reportDict(report));
    } catch (py::error_already_set& e) {
      e.restore();
      throw CallbackRaised{};
    }
  };
  try {
    py::gil_scoped_release release;
    runSequenceJob(cl.job, callbacks);
  } catch (const Error& e) {
    throw PythonError(e.what());
  } catch (const CallbackRaised&) {
    throw py::error_already_set();
  }
  for (const FrameReport& report : done) reports.append(reportDict(report));
  return reports;
}

}  // namespace

void registerResolveSequence(py::module_& module) {
  module.def("resolve_sequence", &resolveSequence, py::arg("color"),
             R"doc(Resolves an EXR sequence exactly as taatool does and returns one dict per frame.

Keyword arguments are taatool's options with '-' written '_':
  output="out.####.exr" (-o), frames="1-24" or [1, 2, 3], depth=, motion=, color_ch=,
  depth_ch=, motion_ch=, preset="cycles", layer=, motion_y="up", motion_to="next",
  motion_scale=, depth_nohit=, jitter="none", jitter_offset=, jitter_period=, blend=,
  clip=False (--no-clip), dilate=False (--no-dilate), pixel_type="float" (-d),
  compression=, gl="osmesa"; any other taatool option by its name.
progress: a callable given each frame's dict after the frame is written.
Raises taa.Error with taatool's message (file, frame, channel) on any failure.)doc");
}

}  // namespace taa::python
