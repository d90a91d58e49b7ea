// SPDX-License-Identifier: MIT
#include "lookahead/planner/ompl_logging.hpp"

#include <ompl/util/Console.h>

namespace lookahead::planner {

void set_ompl_log_level(OmplLogLevel level) {
  switch (level) {
    case OmplLogLevel::kDebug:
      ompl::msg::setLogLevel(ompl::msg::LOG_DEBUG);
      break;
    case OmplLogLevel::kInfo:
      ompl::msg::setLogLevel(ompl::msg::LOG_INFO);
      break;
    case OmplLogLevel::kWarn:
      ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
      break;
    case OmplLogLevel::kError:
      ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
      break;
    case OmplLogLevel::kNone:
      ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
      break;
  }
}

}  // namespace lookahead::planner
