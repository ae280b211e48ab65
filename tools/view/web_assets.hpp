#pragma once
// The page's files (tools/view/web/), built into ifar-view at configure time (CMakeLists.txt), so the view
// needs nothing installed beside it and nothing from the network.

#include <vector>

#include "tools/view/web_server.hpp"

namespace ifar::view {

/// Every file of tools/view/web/ at "/<name>".
std::vector<WebAsset> webAssets();

}  // namespace ifar::view
