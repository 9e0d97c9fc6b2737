// taatool's progress text: frames done of the total, the rate, the time left (issue 24).
#include <gtest/gtest.h>

#include <sstream>

#include "cli/progress_line.h"

namespace taa::cli {
namespace {

TEST(ProgressLine, TextSaysFramesRateAndTimeLeft) {
  EXPECT_EQ(progressText(0, 24, 0.0), "0/24 frames");
  EXPECT_EQ(progressText(12, 24, 6.5), "12/24 frames, 1.85 frames/s, 0:07 left");
  EXPECT_EQ(progressText(24, 24, 13.0), "24/24 frames, 1.85 frames/s");
  EXPECT_EQ(progressText(30, 1000, 2.0), "30/1000 frames, 15.0 frames/s, 1:05 left");
  EXPECT_EQ(progressText(1, 4000, 1.0), "1/4000 frames, 1.00 frames/s, 1:06:39 left");
}

TEST(ProgressLine, OneLineRewrittenOnATerminalALinePerFrameElsewhere) {
  std::ostringstream terminal;
  {
    ProgressLine line(terminal, true);
    line.frameDone(1001, 1, 2);
    line.frameDone(1002, 2, 2);
  }  // the destructor ends the open line
  const std::string text = terminal.str();
  EXPECT_EQ(text.rfind("\rtaatool: 1/2 frames", 0), 0u) << text;
  EXPECT_NE(text.find("\x1b[K\rtaatool: 2/2 frames"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.find('\n'), text.size() - 1);  // one line

  std::ostringstream log;
  ProgressLine plain(log, false);
  plain.frameDone(1001, 1, 2);
  plain.frameDone(1002, 2, 2);
  plain.finish();
  EXPECT_EQ(log.str().rfind("taatool: frame 1001 written, 1/2 frames", 0), 0u) << log.str();
  EXPECT_NE(log.str().find("\ntaatool: frame 1002 written, 2/2 frames"), std::string::npos);
  EXPECT_EQ(log.str().find('\r'), std::string::npos);
}

}  // namespace
}  // namespace taa::cli
