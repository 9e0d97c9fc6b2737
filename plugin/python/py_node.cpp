#include "py_node.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "capi/node_parameters.h"
#include "python_doc.h"
#include "python_error.h"
#include "resolve/option_registry.h"
#include "taa/taa.h"

namespace py = pybind11;

namespace taa::python {
namespace {

// A numpy array seen as a taa_buffer. Keeps the (possibly converted) array alive.
struct ArrayBuffer {
  py::array array;
  taa_buffer buffer{};
};

// numpy's name of an array's element type ("float32", "<U5", "object") for messages.
std::string dtypeName(const py::array& array) {
  return py::str(array.dtype()).cast<std::string>();
}

// The array `object` stands for, with real numeric elements; anything numpy cannot make one of
// (strings, bytes, objects, complex numbers) is refused with its type named. pybind11's
// conversions return a null array instead of raising: it is checked, never dereferenced.
py::array numericArray(const py::handle& object, const std::string& what) {
  py::array array = py::array::ensure(object);
  const char kind = array ? array.dtype().kind() : '?';
  const bool numeric = kind == 'f' || kind == 'i' || kind == 'u' || kind == 'b';
  if (!array || !numeric) {
    const std::string type =
        array ? dtypeName(array) : py::str(py::type::of(object)).cast<std::string>();
    throw PythonError(what + " must be a numeric array (float16/float32, or convertible to "
                      "float32), got " + type);
  }
  return array;
}

// True when a pixel's channels are packed and rows and pixels do not overlap: the C ABI reads
// such an array where it lies (rows may run backwards, as for y_up hosts).
bool stridesFitTheAbi(const py::array& array) {
  const py::ssize_t item = array.itemsize(), channels = array.shape(2);
  return array.strides(2) == item && array.strides(1) >= item * channels &&
         std::abs(array.strides(0)) >= array.strides(1) * array.shape(1);
}

// Native-order float16 and float32 arrays are used in place when their strides fit the C ABI;
// anything else is copied: other byte orders and element types to float32 (float16 keeps its
// type), other layouts (transposed, columns reversed) to a C-contiguous copy. Shapes: (H, W, C),
// or (H, W) for one channel.
ArrayBuffer asBuffer(const py::handle& object, const char* what, int minChannels,
                     int maxChannels) {
  py::array array = numericArray(object, what);
  const bool isHalf = array.dtype().kind() == 'f' && array.itemsize() == 2;
  const bool isFloat = array.dtype().kind() == 'f' && array.itemsize() == 4;
  const bool native = array.dtype().attr("isnative").cast<bool>();
  if (isHalf && !native) {
    array = array.attr("astype")(py::dtype("float16"));
  } else if (!isHalf && !(isFloat && native)) {
    array = py::array_t<float, py::array::forcecast>::ensure(array);
    if (!array) throw PythonError(std::string(what) + " cannot be converted to float32");
  }
  if (array.ndim() == 2 && minChannels == 1) {
    array = array.attr("reshape")(array.shape(0), array.shape(1), 1);
  }
  if (array.ndim() != 3) {
    throw PythonError(std::string(what) + " must have shape (height, width, channels), got " +
                      std::to_string(array.ndim()) + " dimensions");
  }
  const int channels = int(array.shape(2));
  if (channels < minChannels || channels > maxChannels) {
    throw PythonError(std::string(what) + " must have " + std::to_string(minChannels) +
                      (minChannels == maxChannels ? "" : " to " + std::to_string(maxChannels)) +
                      " channels, has " + std::to_string(channels));
  }
  if (!stridesFitTheAbi(array)) {
    array = py::module_::import("numpy").attr("ascontiguousarray")(array);
  }
  ArrayBuffer result;
  result.buffer.data = const_cast<void*>(array.data());
  result.buffer.height = int(array.shape(0));
  result.buffer.width = int(array.shape(1));
  result.buffer.channels = channels;
  result.buffer.type = array.itemsize() == 2 ? TAA_PIXEL_HALF : TAA_PIXEL_FLOAT;
  result.buffer.row_stride_bytes = array.strides(0);
  result.buffer.pixel_stride_bytes = array.strides(1);
  result.array = std::move(array);
  return result;
}

// `count` numbers from any array-like (list, tuple, numpy array), or taa.Error naming `what`.
std::vector<float> numbers(const py::handle& object, std::size_t count, const char* what,
                           const char* meaning) {
  const py::array array = numericArray(object, what);
  const auto values = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!values || std::size_t(values.size()) != count) {
    throw PythonError(std::string(what) + " needs " + std::to_string(count) + " numbers" +
                      meaning);
  }
  return std::vector<float>(values.data(), values.data() + count);
}

class Node {
 public:
  Node(const std::string& gl, const py::kwargs& parameters) {
    taa_create_options options;
    taa_create_options_init(&options);
    if (gl == "egl") {
      options.gl_backend = TAA_GL_EGL;
    } else if (gl == "osmesa") {
      options.gl_backend = TAA_GL_OSMESA;
    } else if (gl != "auto") {
      throw PythonError("gl must be auto, egl or osmesa, got \"" + gl + "\"");
    }
    if (taa_node_create(&options, &node_) != TAA_OK) throw PythonError(taa_last_error());
    for (const auto& [name, value] : parameters) set(name.cast<std::string>(), value);
  }
  ~Node() { taa_node_destroy(node_); }
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  // The value's Python type picks the setter; an int given for a float parameter is accepted.
  void set(const std::string& name, const py::handle& value) {
    taa_status status;
    if (py::isinstance<py::str>(value)) {
      status = taa_node_set_string(node_, name.c_str(), value.cast<std::string>().c_str());
    } else if (py::isinstance<py::bool_>(value) || py::isinstance<py::int_>(value)) {
      status = taa_node_set_int(node_, name.c_str(), value.cast<int>());
      if (status == TAA_ERROR_WRONG_TYPE && !py::isinstance<py::bool_>(value)) {
        status = taa_node_set_float(node_, name.c_str(), value.cast<float>());
      }
    } else {
      status = taa_node_set_float(node_, name.c_str(), value.cast<float>());
    }
    check(status);
    // push returns the resolved frame in history mode, nothing in window mode.
    if (name == "mode") windowMode_ = value.cast<std::string>() == "window";
  }

  py::object push(const py::handle& color, const py::handle& depth, const py::handle& motion,
                  int frame, const py::handle& jitter, bool yUp, const py::handle& worldToCamera,
                  const py::handle& worldToNdc, const py::handle& passes) {
    ArrayBuffer colorBuffer = asBuffer(color, "color", 3, 4);
    std::optional<ArrayBuffer> depthBuffer, motionBuffer;
    if (!depth.is_none()) depthBuffer = asBuffer(depth, "depth", 1, 1);
    if (!motion.is_none()) motionBuffer = asBuffer(motion, "motion", 2, 2);
    for (taa_buffer* b : {&colorBuffer.buffer, depthBuffer ? &depthBuffer->buffer : nullptr,
                          motionBuffer ? &motionBuffer->buffer : nullptr}) {
      if (b) b->y_up = yUp ? 1 : 0;
    }
    taa_frame input;
    taa_frame_init(&input);
    input.frame = frame;
    input.color = &colorBuffer.buffer;
    input.depth = depthBuffer ? &depthBuffer->buffer : nullptr;
    input.motion = motionBuffer ? &motionBuffer->buffer : nullptr;
    if (!jitter.is_none()) {
      const std::vector<float> values =
          numbers(jitter, 2, "jitter", " (x, y): pixels, y down");
      input.has_jitter = 1;
      input.jitter[0] = values[0];
      input.jitter[1] = values[1];
    }
    std::vector<float> w2c, w2ndc;
    if (!worldToCamera.is_none()) {
      w2c = numbers(worldToCamera, 16, "world_to_camera", " (a 4x4 matrix)");
      input.world_to_camera = w2c.data();
    }
    if (!worldToNdc.is_none()) {
      w2ndc = numbers(worldToNdc, 16, "world_to_ndc", " (a 4x4 matrix)");
      input.world_to_ndc = w2ndc.data();
    }

    // The passes: one array a channel, each keeping its type (float16 stays half).
    std::vector<std::string> passNames;
    std::vector<ArrayBuffer> passBuffers;
    std::map<std::string, bool> passHalf;
    if (!passes.is_none()) {
      if (!py::isinstance<py::dict>(passes)) {
        throw PythonError("passes must be a dict of channel name -> (H, W) array");
      }
      for (const auto& [key, value] : passes.cast<py::dict>()) {
        const std::string name = py::str(key).cast<std::string>();
        passBuffers.push_back(asBuffer(value, ("passes['" + name + "']").c_str(), 1, 1));
        passBuffers.back().buffer.y_up = yUp ? 1 : 0;
        passNames.push_back(name);
        passHalf[name] = passBuffers.back().buffer.type == TAA_PIXEL_HALF;
      }
    }
    std::vector<taa_pass> passList;
    for (std::size_t c = 0; c < passNames.size(); ++c) {
      passList.push_back({passNames[c].c_str(), &passBuffers[c].buffer, 0});
    }

    const int height = colorBuffer.buffer.height, width = colorBuffer.buffer.width;
    taa_status status;
    if (windowMode_) {
      {
        py::gil_scoped_release release;
        status = taa_node_push_frame_passes(node_, &input, passList.data(), int(passList.size()));
      }
      check(status);
      frameShape_ = {height, width};  // the ring holds frames of one size: this one's
      passHalf_ = std::move(passHalf);
      return py::none();
    }
    if (!passList.empty()) check(taa_node_push_frame_passes(node_, &input, passList.data(),
                                                            int(passList.size())));
    py::array_t<float> output({height, width, 4});
    taa_buffer out = outputBuffer(output, yUp);
    {
      py::gil_scoped_release release;
      status = taa_node_push_frame(node_, &input);
      if (status == TAA_OK) status = taa_node_read_output(node_, &out);
    }
    check(status);
    return std::move(output);
  }

  py::array_t<float> resolve(int frame, bool yUp) {
    py::array_t<float> output({frameShape_.first, frameShape_.second, 4});
    taa_buffer out = outputBuffer(output, yUp);
    taa_status status;
    {
      py::gil_scoped_release release;
      status = taa_node_resolve_frame(node_, frame);
      if (status == TAA_OK) status = taa_node_read_output(node_, &out);
    }
    check(status);
    return output;
  }

  // The last resolved frame's passes by name (all pushed with the last frame when `names` is
  // None): (H, W) arrays, float16 for channels pushed as float16, else float32.
  py::dict resolvedPasses(const py::handle& names, bool yUp) {
    std::vector<std::string> wanted;
    if (names.is_none()) {
      for (const auto& [name, half] : passHalf_) wanted.push_back(name);
    } else {
      for (const py::handle& name : names) wanted.push_back(py::str(name).cast<std::string>());
    }
    std::vector<py::array> arrays;
    std::vector<taa_buffer> buffers(wanted.size());
    for (std::size_t c = 0; c < wanted.size(); ++c) {
      const auto half = passHalf_.find(wanted[c]);
      const bool isHalf = half != passHalf_.end() && half->second;
      arrays.push_back(isHalf ? py::array(py::dtype("float16"),
                                          {frameShape_.first, frameShape_.second})
                              : py::array(py::dtype("float32"),
                                          {frameShape_.first, frameShape_.second}));
      taa_buffer& b = buffers[c];
      b.data = arrays.back().mutable_data();
      b.height = frameShape_.first;
      b.width = frameShape_.second;
      b.channels = 1;
      b.type = isHalf ? TAA_PIXEL_HALF : TAA_PIXEL_FLOAT;
      b.y_up = yUp ? 1 : 0;
    }
    std::vector<taa_pass> passList;
    for (std::size_t c = 0; c < wanted.size(); ++c) {
      passList.push_back({wanted[c].c_str(), &buffers[c], 0});
    }
    check(taa_node_read_passes(node_, passList.data(), int(passList.size())));
    py::dict result;
    for (std::size_t c = 0; c < wanted.size(); ++c) result[py::str(wanted[c])] = arrays[c];
    return result;
  }

  void drop(int frame) { check(taa_node_drop_frame(node_, frame)); }

  void reset() { check(taa_node_reset_history(node_)); }

 private:
  void check(taa_status status) const {
    if (status == TAA_OK) return;
    // Busy and NULL-handle errors are reported per thread, not on the node.
    const char* message = status == TAA_ERROR_BUSY ? taa_last_error() : taa_node_last_error(node_);
    throw PythonError(message);
  }

  static taa_buffer outputBuffer(py::array_t<float>& output, bool yUp) {
    taa_buffer out{};
    out.data = output.mutable_data();
    out.height = int(output.shape(0));
    out.width = int(output.shape(1));
    out.channels = 4;
    out.type = TAA_PIXEL_FLOAT;
    out.y_up = yUp ? 1 : 0;
    return out;
  }

  taa_node* node_ = nullptr;
  bool windowMode_ = false;
  std::pair<int, int> frameShape_{0, 0};  // window mode: height, width of the pushed frames
  std::map<std::string, bool> passHalf_;  // the last pushed frame's passes: float16 or not
};

// The class documentation: what a node is, then every parameter from the option registry and
// the node's own table (so it cannot drift from what the node accepts).
std::string nodeDoc() {
  return R"doc(A resolve node with its own OpenGL context, on the C ABI.

Node(gl="auto", **parameters): parameters by taatool's option names with '_' for '-', e.g.
Node(preset="cycles", camera_sidecar="camera.json", blend=0.1). History mode by default: push()
resolves each frame. mode="window", window=K: push() puts frames into a ring of 2K+1 and
returns None; resolve(t) rebuilds frame t from the pushed frames within K of it (taatool
--mode window), in any order. One thread at a time per node; different nodes may run in
parallel threads.

)doc" + optionsDoc("Resolve options (taatool's --NAME):", resolveOptionList()) + "\n" +
         optionsDoc("Input conventions and the node's own:", capi::nodeInputParameterInfo());
}

}  // namespace

void registerNode(py::module_& module) {
  static const std::string doc = nodeDoc();
  py::class_<Node>(module, "Node", doc.c_str())
      .def(py::init<const std::string&, const py::kwargs&>(), py::arg("gl") = "auto")
      .def("set", &Node::set, py::arg("name"), py::arg("value"),
           "Sets one parameter (see the class doc); raises taa.Error naming a bad one.")
      .def("push", &Node::push, py::arg("color"), py::arg("depth") = py::none(),
           py::arg("motion") = py::none(), py::arg("frame") = 0, py::arg("jitter") = py::none(),
           py::arg("y_up") = false, py::arg("world_to_camera") = py::none(),
           py::arg("world_to_ndc") = py::none(), py::arg("passes") = py::none(),
           R"doc(Resolves one frame and returns RGBA float32 of shape (height, width, 4).
In window mode, puts the frame into the ring instead and returns None (see resolve).

color: (H, W, 3|4) float16/float32 (others are converted), premultiplied; depth: (H, W) or
(H, W, 1); motion: (H, W, 2) in pixels, converted by the motion_* parameters. frame: the
frame number (Halton jitter index; a gap resets history, or ends a window). jitter: (x, y) in
pixels, y down, instead of Halton. y_up: row 0 of every array, output included, is the bottom
row. world_to_camera, world_to_ndc: 16 values each, row-major as in EXR headers. passes (window
mode): the render's other channels, {name: (H, W) array}, named as the render names them
("ViewLayer.DiffDir.R"); each keeps its type (float16 light passes stay half), its kind comes
from its name or the "aov" parameter, and it is resolved with the colour's weights (taatool's
"Every pass of the render"); read them with passes().)doc")
      .def("resolve", &Node::resolve, py::arg("frame"), py::arg("y_up") = false,
           R"doc(Window mode: resolves `frame` from the pushed frames within K of it (consecutive,
in its shot) and returns RGBA float32 of shape (height, width, 4). Push every existing frame
of the window first: a frame that was evicted from the full ring (the farthest from the one
pushed), dropped or removed by a parameter change raises taa.Error naming it.)doc")
      .def("passes", &Node::resolvedPasses, py::arg("names") = py::none(),
           py::arg("y_up") = false,
           R"doc(Window mode: the passes of the frame resolve() resolved last, {name: (H, W)
array} (float16 where pushed as float16, else float32), every channel pushed with the last
frame or those `names` lists; taatool's values bit for bit. Raises taa.Error for a name the
frame did not have.)doc")
      .def("drop", &Node::drop, py::arg("frame"),
           "Window mode: takes a frame out of the ring (windows that need it fail until it is "
           "pushed again).")
      .def("reset", &Node::reset,
           "Forgets history: the next frame stands alone (a cut). Window mode: the next pushed "
           "frame starts a new shot.");
}

}  // namespace taa::python
