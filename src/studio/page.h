#pragma once
// The page's files (src/studio/page/), embedded in the binary at build time
// by cmake/embed_files.cmake: the studio serves these and nothing else.
#include <string_view>

namespace sandpic::studio {

struct PageFile {
  std::string_view name;  // "index.html", "app.js"
  std::string_view body;
};

// nullptr when `name` is not one of the page's files.
const PageFile* page_file(std::string_view name);
std::string_view content_type(std::string_view name);

}  // namespace sandpic::studio
