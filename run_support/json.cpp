#include "json.h"

namespace specular {
namespace tb {

std::string dump_json(const Json& json) {
  return json.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace tb
}  // namespace specular
