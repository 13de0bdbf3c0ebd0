#pragma once
// Moved to granular/model/contact_law.hpp; this forwarding header goes once every branch has moved.
#include "granular/model/contact_law.hpp"
