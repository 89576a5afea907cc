#include <gtest/gtest.h>

#include "catena/pocketwheel/run_on.hpp"

TEST(PocketwheelPaper, Placeholder) { SUCCEED(); }
