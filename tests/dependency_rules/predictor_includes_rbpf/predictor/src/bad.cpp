// SPDX-License-Identifier: MIT
// A forbidden include: the dependency rules must reject this tree.
#include "lookahead/slam/rbpf/rbpf.hpp"
