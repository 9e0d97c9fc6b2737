#include "io/camera_note.h"

namespace taa::io {

bool isCameraNote(const std::string& text) {
  return text.rfind(kCameraNoteFamily, 0) == 0;
}

SidecarFrame parseCameraNote(const std::string& text, ErrorContext context) {
  context.channel = kCameraNoteAttribute;
  const std::size_t space = text.find(' ');
  const std::string version = text.substr(0, space);
  if (version != kCameraNoteVersion) {
    throw Error("the header's camera note is \"" + version.substr(0, 40) + "\"; this taa reads \"" +
                    kCameraNoteVersion + "\"",
                context);
  }
  if (space == std::string::npos) {
    throw Error("the header's camera note has no entry after \"" + version + "\"", context);
  }
  return parseCameraEntry(text.substr(space + 1),
                          {"camera note entry", "the header's camera note"}, context);
}

std::optional<SidecarFrame> readCameraNote(const OIIO::ImageSpec& header, const std::string& path,
                                           int frame) {
  const OIIO::ParamValue* note = header.find_attribute(kCameraNoteAttribute, OIIO::TypeString);
  if (!note) return std::nullopt;
  const std::string text = note->get_string();
  if (!isCameraNote(text)) return std::nullopt;
  return parseCameraNote(text, {path, frame, ""});
}

}  // namespace taa::io
