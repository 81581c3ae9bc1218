#pragma once

class DemoMotion;

namespace lk::system {
class SignalWatcher;
}
namespace lk::ui {
class MainWindow;
}

/// How lkstudio's ways of ending reach the window's LeaveGuard, so that nothing it set moving
/// is left turning unasked: termination signals and logout (the close button, Ctrl+Q and
/// Disconnect are the window's own).
class LeaveHooks {
public:
    /// SIGTERM and SIGINT (systemd, kill, Ctrl-C in a terminal) close the window as its close
    /// button does (settings saved, the bus thread ended), stopping the drives commanded to
    /// move without asking: nobody may be there to answer.
    static void closeOnTermination(lk::ui::MainWindow &window, lk::system::SignalWatcher &watcher);
    /// A logout (QGuiApplication::commitDataRequest) asks as a quit does when the session
    /// manager allows it, and stops without asking when it does not; "Cancel" cancels the
    /// logout.
    static void askBeforeLogout(lk::ui::MainWindow &window);
    /// While the demo runs, the drives it moves are the only ones commanded: leaving stops them
    /// without asking (they are simulated inside lkstudio).
    static void followDemo(lk::ui::MainWindow &window, DemoMotion &demo);
};
