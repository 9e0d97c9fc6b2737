// The exported C functions of taa.h. Every entry point catches everything: no C++ exception
// crosses the ABI. Node calls are serialised by a try-lock, so a second thread gets
// TAA_ERROR_BUSY instead of racing on the GL context.
#include <mutex>
#include <new>
#include <string>

#include <vector>

#include "capi/host_enum.h"
#include "capi/node.h"
#include "capi/status_error.h"
#include "taa/error.h"
#include "taa/taa.h"
#include "taa/version.h"
#include "util/frame_buffer_pool.h"

struct taa_node {
  std::mutex busy;
  std::string lastError;
  std::unique_ptr<taa::capi::Node> node;
};

namespace {

using taa::capi::StatusError;

// Errors of calls that have no node to hold them (NULL handle, failed create, busy).
thread_local std::string threadError;

taa_status failWithoutNode(taa_status status, const std::string& message) {
  threadError = message;
  return status;
}

// Runs `body` on a locked node, turning any exception into a status and the node's message.
template <class Body>
taa_status guarded(taa_node* handle, const char* function, Body&& body) {
  if (!handle) {
    return failWithoutNode(TAA_ERROR_INVALID_ARGUMENT,
                           std::string(function) + ": node is NULL");
  }
  std::unique_lock<std::mutex> lock(handle->busy, std::try_to_lock);
  if (!lock.owns_lock()) {
    return failWithoutNode(TAA_ERROR_BUSY, std::string(function) +
                                               ": node is in use by another thread");
  }
  handle->lastError.clear();
  try {
    body(*handle->node);
    return TAA_OK;
  } catch (const StatusError& e) {
    handle->lastError = e.what();
    return e.status();
  } catch (const std::bad_alloc&) {
    handle->lastError = std::string(function) + ": out of memory";
  } catch (const std::exception& e) {
    handle->lastError = std::string(function) + ": " + e.what();
  } catch (...) {
    handle->lastError = std::string(function) + ": unknown error";
  }
  return TAA_ERROR_INTERNAL;
}

taa::gl::Backend toBackend(const taa_gl_backend& backend) {
  switch (taa::capi::hostEnumValue(backend)) {
    case TAA_GL_AUTO: return taa::gl::Backend::Auto;
    case TAA_GL_EGL: return taa::gl::Backend::Egl;
    case TAA_GL_OSMESA: return taa::gl::Backend::OsMesa;
  }
  throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                    "unknown GL back end " + std::to_string(taa::capi::hostEnumValue(backend)));
}

std::string nameOrThrow(const char* name) {
  if (!name) throw StatusError(TAA_ERROR_INVALID_ARGUMENT, "parameter name is NULL");
  return name;
}

}  // namespace

extern "C" {

int taa_abi_version(void) { return TAA_ABI_VERSION; }

const char* taa_version_string(void) { return TAA_VERSION_STRING; }

const char* taa_last_error(void) { return threadError.c_str(); }

void taa_create_options_init(taa_create_options* options) {
  if (!options) return;
  options->gl_backend = TAA_GL_AUTO;
  options->defer_context = 0;
}

void taa_frame_init(taa_frame* frame) {
  if (!frame) return;
  *frame = taa_frame{};
}

taa_status taa_node_create(const taa_create_options* options, taa_node** node) {
  if (!node) return failWithoutNode(TAA_ERROR_INVALID_ARGUMENT, "taa_node_create: node is NULL");
  *node = nullptr;
  taa_create_options defaults;
  taa_create_options_init(&defaults);
  const taa_create_options& chosen = options ? *options : defaults;
  try {
    auto handle = std::make_unique<taa_node>();
    handle->node = std::make_unique<taa::capi::Node>(toBackend(chosen.gl_backend),
                                                     chosen.defer_context != 0);
    *node = handle.release();
    threadError.clear();
    return TAA_OK;
  } catch (const StatusError& e) {
    return failWithoutNode(e.status(), std::string("taa_node_create: ") + e.what());
  } catch (const std::exception& e) {
    return failWithoutNode(TAA_ERROR_INTERNAL, std::string("taa_node_create: ") + e.what());
  } catch (...) {
    return failWithoutNode(TAA_ERROR_INTERNAL, "taa_node_create: unknown error");
  }
}

void taa_node_destroy(taa_node* node) {
  if (!node) return;
  try {
    // Waits for a call still running on another thread rather than pulling its context away.
    { std::lock_guard<std::mutex> wait(node->busy); }
    delete node;
    taa::releaseFrameBuffers();  // the host gets the frame buffers taa kept back
  } catch (...) {
    // Destruction reports nothing: a GL failure while freeing leaves nothing to recover.
  }
}

const char* taa_node_last_error(const taa_node* node) {
  return node ? node->lastError.c_str() : "taa_node_last_error: node is NULL";
}

taa_status taa_node_set_int(taa_node* node, const char* name, int value) {
  return guarded(node, "taa_node_set_int",
                 [&](taa::capi::Node& n) { n.setInt(nameOrThrow(name), value); });
}

taa_status taa_node_set_float(taa_node* node, const char* name, float value) {
  return guarded(node, "taa_node_set_float",
                 [&](taa::capi::Node& n) { n.setFloat(nameOrThrow(name), value); });
}

taa_status taa_node_set_string(taa_node* node, const char* name, const char* value) {
  return guarded(node, "taa_node_set_string", [&](taa::capi::Node& n) {
    if (!value) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                        "parameter \"" + nameOrThrow(name) + "\": value is NULL");
    }
    n.setString(nameOrThrow(name), value);
  });
}

taa_status taa_node_push_frame(taa_node* node, const taa_frame* frame) {
  return guarded(node, "taa_node_push_frame", [&](taa::capi::Node& n) {
    if (!frame) throw StatusError(TAA_ERROR_INVALID_ARGUMENT, "frame is NULL");
    n.pushFrame(*frame, {});
  });
}

taa_status taa_node_push_frame_passes(taa_node* node, const taa_frame* frame,
                                      const taa_pass* passes, int count) {
  return guarded(node, "taa_node_push_frame_passes", [&](taa::capi::Node& n) {
    if (!frame) throw StatusError(TAA_ERROR_INVALID_ARGUMENT, "frame is NULL");
    if (count < 0 || (count > 0 && !passes)) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT, "passes is NULL or count negative");
    }
    n.pushFrame(*frame, count > 0 ? std::vector<taa_pass>(passes, passes + count)
                                  : std::vector<taa_pass>());
  });
}

taa_status taa_node_read_passes(taa_node* node, const taa_pass* passes, int count) {
  return guarded(node, "taa_node_read_passes", [&](taa::capi::Node& n) {
    if (count < 0 || (count > 0 && !passes)) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT, "passes is NULL or count negative");
    }
    n.readPasses(std::vector<taa_pass>(passes, passes + count));
  });
}

taa_status taa_node_resolve_frame(taa_node* node, int frame) {
  return guarded(node, "taa_node_resolve_frame",
                 [&](taa::capi::Node& n) { n.resolveFrame(frame); });
}

taa_status taa_node_drop_frame(taa_node* node, int frame) {
  return guarded(node, "taa_node_drop_frame", [&](taa::capi::Node& n) { n.dropFrame(frame); });
}

taa_status taa_node_read_output(taa_node* node, const taa_buffer* output) {
  return guarded(node, "taa_node_read_output", [&](taa::capi::Node& n) {
    if (!output) throw StatusError(TAA_ERROR_INVALID_ARGUMENT, "output buffer is NULL");
    n.readOutput(*output);
  });
}

taa_status taa_node_get_camera(taa_node* node, float world_to_camera[16],
                               float world_to_ndc[16]) {
  return guarded(node, "taa_node_get_camera",
                 [&](taa::capi::Node& n) { n.cameras(world_to_camera, world_to_ndc); });
}

taa_status taa_node_reset_history(taa_node* node) {
  return guarded(node, "taa_node_reset_history", [](taa::capi::Node& n) { n.resetHistory(); });
}

}  // extern "C"
