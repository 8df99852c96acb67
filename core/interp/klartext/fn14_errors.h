#pragma once

namespace kerf::klartext {

// The control's predefined texts for FN 14 error numbers 1000 to 1099; nullptr when the number
// has none (0..999 are the machine builder's).
const char* fn14ErrorText(int number);

}  // namespace kerf::klartext
