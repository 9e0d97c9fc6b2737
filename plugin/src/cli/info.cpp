#include "cli/info.h"

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imageio.h>

#include <string>

#include "color/ocio_bracket.h"
#include "gl/self_test.h"
#include "taa/version.h"

namespace taa::cli {

int printInfo(gl::Backend backend, const gl::LogSink& log, std::ostream& out) {
  auto context = gl::Context::create(backend, log);
  const gl::ContextInfo& info = context->info();
  const gl::SelfTestResult selfTest = gl::runSelfTest(*context);
  const int oiio = OIIO::openimageio_version();
  out << "taa " << TAA_VERSION_STRING << "\n"
      << "GL back end:     " << gl::backendName(info.backend) << " (" << info.platform << ")\n"
      << "GL vendor:       " << info.vendor << "\n"
      << "GL renderer:     " << info.renderer << "\n"
      << "GL version:      " << info.version << "\n"
      << "GLSL version:    " << info.glslVersion << "\n"
      << "Image stores:    "
      << (info.fragmentImageUnits > 0
              ? std::to_string(info.fragmentImageUnits) +
                    " images a shader (the passes' gather in one draw)"
              : std::string("none (the passes' gather in draws of six groups)"))
      << "\n"
      << "GL self-test:    " << (selfTest.passed ? "passed" : "FAILED") << " ("
      << selfTest.detail << ")\n"
      << "OpenColorIO:     " << OCIO_NAMESPACE::GetVersion() << "\n"
      << "OpenImageIO:     " << oiio / 10000 << "." << (oiio / 100) % 100 << "." << oiio % 100
      << "\n";
  return selfTest.passed ? 0 : 1;
}

void printBrackets(const std::string& ocioConfig, std::ostream& out) {
  const color::LoadedConfig loaded = color::loadConfig(ocioConfig);
  out << "OCIO config: " << loaded.description << "\n";
  for (const std::string& name : color::listBrackets(loaded.config)) {
    out << "  " << name << "\n";
  }
}

}  // namespace taa::cli
