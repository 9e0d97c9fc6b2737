// taa-farm: taa's resolve as a render-farm step (farm/verbs.h). Exit statuses mean something to
// a scheduler: 0 done, 1 resolve error, 2 bad arguments, 3 inputs not ready, 128 + the signal
// when SIGINT or SIGTERM stopped it. Every failure is printed here as
// "taa-farm ERROR: <what> : <file> (frame N, channel C)".
#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "farm/farm_arguments.h"
#include "farm/farm_errors.h"
#include "farm/verbs.h"
#include "util/frame_memory.h"
#include "util/interruption.h"

namespace {

constexpr int kResolveError = 1, kUsageError = 2, kInputsNotReady = 3;

int run(const std::vector<std::string>& argv) {
  using namespace taa::farm;
  const FarmArguments args = parseFarmArguments(argv);
  if (args.help) {
    std::cout << farmHelpText();
    return 0;
  }
  if (args.verb == "submit") return submitShot(args);
  if (args.verb == "run") return runChunk(args);
  return reportStatus(args);
}

}  // namespace

int main(int argc, char** argv) {
  taa::keepFrameBuffersOutOfTheHeap();
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const taa::farm::UsageError& e) {
    std::cerr << "taa-farm ERROR: " << e.what() << " (see taa-farm --help)" << std::endl;
    return kUsageError;
  } catch (const taa::farm::InputsNotReady& e) {
    std::cerr << "taa-farm ERROR: " << e.what() << std::endl;
    return kInputsNotReady;
  } catch (const taa::Stopped& e) {
    const int signal = taa::StopSignals::received();
    std::cerr << "taa-farm ERROR: interrupted by " << (signal == SIGINT ? "SIGINT" : "SIGTERM")
              << ": " << e.what() << std::endl;
    return 128 + signal;
  } catch (const std::exception& e) {
    std::cerr << "taa-farm ERROR: " << e.what() << std::endl;
    return kResolveError;
  }
}
