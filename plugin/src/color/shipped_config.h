// taa's own OCIO config (ocio/config.ocio), embedded at build time so that it works with no
// file lookup and no $OCIO.
#pragma once

namespace taa::color {

// The text of ocio/config.ocio. Defined in the generated shipped_config.cpp.
const char* shippedConfigText();

}  // namespace taa::color
