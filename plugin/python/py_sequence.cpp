#include "py_sequence.h"

#include <optional>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/input_report.h"
#include "python_doc.h"
#include "python_error.h"
#include "resolve/option_registry.h"
#include "resolve/sequence_job.h"
#include "taa/error.h"
#include "util/interruption.h"

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

// A str, bytes or os.PathLike as the bytes the file system sees (os.fsencode): a name that is
// not UTF-8 (bytes, or a str holding surrogate escapes, as os.listdir gives it) reaches the
// file as it is.
bool isPathLike(const py::handle& value) {
  return py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
         py::hasattr(value, "__fspath__");
}
std::string fileSystemText(const py::handle& value) {
  return py::module_::import("os").attr("fsencode")(value).cast<std::string>();
}
// Back to Python as os.fsdecode gives it: the file system's bytes, surrogate-escaped.
py::object fileSystemName(const std::string& text) {
  return py::module_::import("os").attr("fsdecode")(py::bytes(text));
}

// taatool's argument list for these keyword arguments, so that the options mean exactly what
// they mean on the command line (and are checked by the same code).
std::vector<std::string> commandLine(const py::object& color, const py::kwargs& kwargs,
                                     py::object& progress) {
  std::vector<std::string> args = {fileSystemText(color)};
  for (const auto& [keyHandle, value] : kwargs) {
    const std::string key = keyHandle.cast<std::string>();
    if (key == "progress") {
      progress = py::reinterpret_borrow<py::object>(value);
      continue;
    }
    if (value.is_none()) continue;
    std::string flag = "--" + key;
    for (char& c : flag) c = c == '_' ? '-' : c;
    if (auto special = specialFlag(key)) flag = *special;
    if (py::isinstance<py::bool_>(value)) {
      if (value.cast<bool>()) {
        args.push_back(flag);
      } else if (!cli::isSwitchOption(flag)) {  // False leaves a switch out; anything else
        throw Error("unknown option " + flag + " (see taatool --help; given as " + key +
                    "=False)");
      }
    } else if (key == "frames") {
      args.insert(args.end(), {flag, framesText(value)});
    } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      // A list repeats the option, as taatool's repeatable ones (--aov) are given.
      for (const py::handle& item : value) {
        args.insert(args.end(), {flag, isPathLike(item) ? fileSystemText(item)
                                                        : py::str(item).cast<std::string>()});
      }
    } else if (isPathLike(value)) {
      args.insert(args.end(), {flag, fileSystemText(value)});
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
  d["input"] = fileSystemName(report.inputPath);
  d["output"] = fileSystemName(report.outputPath);
  d["history_reset"] = report.historyReset;
  d["size_changed"] = report.sizeChanged;
  d["non_finite_color_values"] = report.nonFiniteColorValues;
  d["non_finite_motion_values"] = report.nonFiniteMotionValues;
  d["clamped_color_values"] = report.clampedColorValues;
  return d;
}

// Thrown through the job when the progress callback raised; the Python error stays set.
struct CallbackRaised {};

py::list resolveSequence(const py::object& color, const py::kwargs& kwargs) {
  py::object progress = py::none();
  cli::CommandLine cl;
  std::optional<cli::InputReport> inputReport;
  try {
    cl = cli::parseCommandLine(commandLine(color, kwargs, progress));
    cli::resolveFrameList(cl);
    inputReport.emplace(cl);
  } catch (const Error& e) {
    throw PythonError(e.what());
  }

  py::list reports;
  std::vector<FrameReport> done;
  JobCallbacks callbacks;
  callbacks.frameRead = [&](const FrameReport& report) { inputReport->frameRead(report); };
  // Ctrl-C (or any signal whose Python handler raises) stops the job between frames; the
  // Python exception stays set and is raised once the frames in flight are written.
  bool signalRaised = false;
  callbacks.stopRequested = [&] {
    py::gil_scoped_acquire gil;
    signalRaised = signalRaised || PyErr_CheckSignals() != 0;
    return signalRaised;
  };
  callbacks.frameDone = [&](const FrameReport& report) {
    done.push_back(report);
    if (progress.is_none() || signalRaised) return;  // no Python code while an error is set
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
  } catch (const Stopped&) {
    if (signalRaised) throw py::error_already_set();
    throw;
  } catch (const Error& e) {
    throw PythonError(e.what());
  } catch (const CallbackRaised&) {
    throw py::error_already_set();
  }
  // What changed the result silently, as Python warnings (taatool prints them on stderr).
  // A file name in a warning may not be UTF-8: its bytes are kept as \xNN escapes. A warning
  // turned into an error (-W error) raises from warn.
  const py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& warning : inputReport->warnings()) {
    warn(py::reinterpret_steal<py::object>(PyUnicode_DecodeUTF8(
             warning.data(), Py_ssize_t(warning.size()), "backslashreplace")),
         py::handle(PyExc_RuntimeWarning), 1);
  }
  for (const FrameReport& report : done) reports.append(reportDict(report));
  return reports;
}

// The function's documentation: how it runs, then every keyword, from taatool's own option
// tables (the option registry and --help), so it names exactly what the parser takes.
std::string resolveSequenceDoc() {
  return R"doc(Resolves an EXR sequence exactly as taatool does and returns one dict per frame.

resolve_sequence(color, **options): color is taatool's COLOR_PATTERN; every keyword is a
taatool option with '_' for '-' (a flag as True), e.g. output="out.####.exr" (-o),
frames="1-24" or [1, 2, 3], pixel_type="float" (-d), preset="cycles",
camera_sidecar="camera.json", skip_missing=True, strict=True; a list repeats an option, e.g.
aov=["DiffCol.*=copy", "*=drop"] (the render's passes: --aov).
progress: a callable given each frame's dict after the frame is written.
What changed the result silently is reported as RuntimeWarning with counts, as taatool's
warnings (strict=True: an error instead). Ctrl-C stops between frames: frames written are
complete, KeyboardInterrupt follows. Raises taa.Error with taatool's message (file, frame,
channel) on any failure, an unknown keyword included.

)doc" + sequenceOptionsDoc() + "\n" + optionsDoc("Resolve options:", resolveOptionList());
}

}  // namespace

void registerResolveSequence(py::module_& module) {
  static const std::string doc = resolveSequenceDoc();
  module.def("resolve_sequence", &resolveSequence, py::arg("color"), doc.c_str());
}

}  // namespace taa::python
