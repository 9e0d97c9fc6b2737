#include "cli/view_selection.h"

#include <filesystem>

#include "io/sequence_pattern.h"
#include "io/views.h"
#include "taa/error.h"

namespace taa::cli {

void selectViews(CommandLine& cl) {
  cl.job.views.clear();
  const std::string asked = cl.viewText.empty() ? "all" : cl.viewText;
  if (cl.job.frames.empty()) return;
  const int first = cl.job.frames.front();
  const std::string path = io::expandFramePattern(cl.job.layout.color.pattern, first);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return;  // the job's checks name it
  const io::FileViews views = io::readViews(path);
  if (views.names.empty()) {
    if (asked != "all") {
      throw Error("--view " + asked + " has no effect: the color file is not multi-view (no "
                  "multiView attribute, no part with a view)",
                  {path, first, ""});
    }
    return;
  }
  std::string names;
  for (const std::string& name : views.names) names += (names.empty() ? "" : ", ") + name;
  for (std::size_t i = 0; i < views.names.size(); ++i) {
    if (asked == "all" || asked == views.names[i]) {
      cl.job.views.push_back({views.names[i], io::layoutForView(cl.job.layout, views, i)});
    }
  }
  if (cl.job.views.empty()) {
    throw Error("the color file has no view " + asked + " (its views: " + names + ")",
                {path, first, ""});
  }
  if (cl.job.views.size() > 1 && !cl.job.outputChannels.empty()) {
    throw Error("--out-ch names one view's channels, and the file's views " + names +
                " are resolved together: pick one with --view");
  }
  if (cl.job.views.size() > 1 && cl.job.debugLayers) {
    throw Error("--debug-layers shows one view, and the file's views " + names +
                " are resolved together: pick one with --view");
  }
}

}  // namespace taa::cli
