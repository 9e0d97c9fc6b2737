// Views of a multi-view EXR (io/views.h): found from the multiView attribute or the parts'
// view attributes, and each view's channel names or part.
#include <gtest/gtest.h>

#include "io/frame_reader.h"
#include "io/views.h"
#include "test_files.h"

namespace taa::io {
namespace {

TEST(Views, ChannelNamesCarryTheViewBeforeTheirLastComponent) {
  EXPECT_EQ(viewChannelName("ViewLayer.Combined.R", "left"), "ViewLayer.Combined.left.R");
  EXPECT_EQ(viewChannelName("R", "right"), "right.R");
  EXPECT_EQ(viewChannelName("depth.Z", "left"), "depth.left.Z");
}

// A one-part file's channels belong to the view named before their last component, else to
// the default view; a pass's kind is read from its name without the view.
TEST(Views, ChannelsBelongToTheViewInTheirNameElseTheDefaultOne) {
  const std::vector<std::string> views = {"left", "right"};
  EXPECT_EQ(viewOfChannel("ViewLayer.DiffDir.right.R", views), "right");
  EXPECT_EQ(viewOfChannel("ViewLayer.DiffDir.left.R", views), "left");
  EXPECT_EQ(viewOfChannel("right.Z", views), "right");
  EXPECT_EQ(viewOfChannel("Z", views), "left");
  EXPECT_EQ(viewOfChannel("ViewLayer.Normal.X", views), "left");
  EXPECT_EQ(viewOfChannel("right.layer.R", views), "left");  // a layer named like a view
  EXPECT_EQ(withoutView("ViewLayer.DiffDir.left.R", "left"), "ViewLayer.DiffDir.R");
  EXPECT_EQ(withoutView("right.Z", "right"), "Z");
  EXPECT_EQ(withoutView("ViewLayer.DiffDir.R", "left"), "ViewLayer.DiffDir.R");
  EXPECT_EQ(withoutView("Aleft.R", "left"), "Aleft.R");  // a component, not a suffix
  EXPECT_EQ(withoutView("ViewLayer.DiffDir.left.R", ""), "ViewLayer.DiffDir.left.R");
}

TEST(Views, OnePartWithMultiView) {
  const std::string path = test::scratchFolder() + "/stereo.exr";
  // Nuke's way: the default view (left) without a view in its names, the other with.
  OIIO::ImageSpec spec = test::makeSpec(4, 2, {"R", "G", "B", "A", "right.R", "right.G",
                                               "right.B", "right.A", "Z", "right.Z"});
  const char* names[] = {"left", "right"};
  spec.attribute("multiView", OIIO::TypeDesc(OIIO::TypeDesc::STRING, 2), names);
  std::vector<float> pixels(4 * 2 * 10);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i % 10);
  test::writeImage(path, spec, pixels);

  const FileViews views = readViews(path);
  EXPECT_EQ(views.names, (std::vector<std::string>{"left", "right"}));
  EXPECT_TRUE(views.parts.empty());
  AovLayout base;
  base.color = {path, {"R", "G", "B", "A"}, ""};
  base.depth = AovSource{"", {"Z"}, ""};
  base.passthrough = {"*"};
  const AovLayout left = layoutForView(base, views, 0);
  const AovLayout right = layoutForView(base, views, 1);
  EXPECT_EQ(left.color.channels, (std::vector<std::string>{"R", "G", "B", "A"}));
  EXPECT_EQ(right.color.channels,
            (std::vector<std::string>{"right.R", "right.G", "right.B", "right.A"}));
  EXPECT_EQ(right.depth->channels, std::vector<std::string>{"right.Z"});
  EXPECT_TRUE(right.passthrough.empty());  // pass-through goes with the first view
  // Each view's pixels are its own.
  EXPECT_EQ(readFrame(left, 1).depth.pixels[0], 8.0f);
  EXPECT_EQ(readFrame(right, 1).depth.pixels[0], 9.0f);
  EXPECT_EQ(readFrame(right, 1).color.toFloat().pixels[0], 4.0f);
}

TEST(Views, OnePartPerView) {
  const std::string path = test::scratchFolder() + "/parts.exr";
  std::vector<OIIO::ImageSpec> specs;
  for (const char* view : {"left", "right"}) {
    OIIO::ImageSpec spec = test::makeSpec(2, 2, {"R", "G", "B", "A"});
    spec.attribute("view", view);
    spec.attribute("name", std::string("rgba.") + view);
    specs.push_back(spec);
  }
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out && out->open(path, int(specs.size()), specs.data()));
  for (std::size_t part = 0; part < specs.size(); ++part) {
    if (part > 0) {
      ASSERT_TRUE(out->open(path, specs[part], OIIO::ImageOutput::AppendSubimage));
    }
    const std::vector<float> pixels(2 * 2 * 4, float(part + 1));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
  }
  ASSERT_TRUE(out->close());

  const FileViews views = readViews(path);
  EXPECT_EQ(views.names, (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(views.parts, (std::vector<std::string>{"rgba.left", "rgba.right"}));
  AovLayout base;
  base.color = {path, {"R", "G", "B", "A"}, ""};
  const AovLayout right = layoutForView(base, views, 1);
  EXPECT_EQ(right.color.part, "rgba.right");
  EXPECT_EQ(right.color.channels, (std::vector<std::string>{"R", "G", "B", "A"}));
  // Written with the view in its names (the output is one part); its passes its own part's.
  EXPECT_EQ(right.partView, "right");
  EXPECT_EQ(layoutForView(base, views, 0).partView, "");
  base.passes = true;
  EXPECT_TRUE(layoutForView(base, views, 1).passes);
  EXPECT_EQ(readFrame(right, 1).color.toFloat().pixels[0], 2.0f);
}

TEST(Views, AFileWithoutViewsHasNone) {
  const std::string path = test::scratchFolder() + "/plain.exr";
  test::writeImage(path, test::makeSpec(2, 2, {"R", "G", "B"}), std::vector<float>(12));
  EXPECT_TRUE(readViews(path).names.empty());
}

}  // namespace
}  // namespace taa::io
