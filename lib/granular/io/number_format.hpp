#pragma once
// Moved to granular/number_format.hpp; this forwarding header goes once every branch has moved.
#include "granular/number_format.hpp"
