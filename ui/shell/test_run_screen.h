#pragma once

namespace kerf::ui {

class MainWindow;

// For `kerf --mode testrun --screenshot`: plays the open program's test run at full speed and
// waits (at most `timeoutMs`) until the graphics show the finished stock in a view fitted to the
// content: woken by the run, the stock and the fit, never by a guessed delay. False on time-out.
bool finishTestRunForPicture(MainWindow& window, int timeoutMs = 60000);

}  // namespace kerf::ui
