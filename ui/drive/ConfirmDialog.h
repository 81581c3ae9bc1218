#pragma once

#include <QtCore/QString>
#include <QtWidgets/QDialog>

#include <functional>

namespace lk::ui {

/// What a confirmation asks: the action, why it needs asking, and the button that goes ahead.
struct ConfirmRequest {
    QString key;        ///< stable name for policies and tests, e.g. "write_pid_rom"
    QString title;      ///< window title
    QString question;   ///< "Write these gains to the ROM of drive 3?"
    QString reason;     ///< why it is asked: "ROM writes wear the drive's flash ..."
    QString acceptText; ///< the button that goes ahead, e.g. "Write to ROM"
};

/// Asks before a write that cannot be taken back (flash wear, power cycle). Cancel is the
/// default button, so Enter never writes by accident, and Esc rejects it (in lkstudio the
/// application-wide emergency stop sees that Esc too). Tests install a Policy that answers
/// instead of the user, so they never block on a modal dialog.
class ConfirmDialog : public QDialog {
    Q_OBJECT
public:
    using Policy = std::function<bool(const ConfirmRequest &)>;

    explicit ConfirmDialog(const ConfirmRequest &request, QWidget *parent = nullptr);

    /// Shows the dialog modally (or asks the installed policy) and returns the answer.
    static bool ask(QWidget *parent, const ConfirmRequest &request);

    /// ask(), for an action whose target may change while the dialog is open (its event loop
    /// runs): true to go ahead only when the answer was yes and `unchanged()` still holds.
    /// Otherwise `why` gets the sentence to show ("Cancelled: nothing was sent." or that the
    /// drive or connection changed) and `changed` whether it was the latter (an error).
    static bool askUnchanged(QWidget *parent, const ConfirmRequest &request,
                             const std::function<bool()> &unchanged, QString *why, bool *changed);

    /// Answer every question with `policy` instead of a dialog (tests); empty: ask the user.
    static void setPolicy(Policy policy);

    /// Installs a policy for the lifetime of the object (tests).
    class ScopedPolicy {
    public:
        explicit ScopedPolicy(Policy policy) { setPolicy(std::move(policy)); }
        ~ScopedPolicy() { setPolicy({}); }
        ScopedPolicy(const ScopedPolicy &) = delete;
        ScopedPolicy &operator=(const ScopedPolicy &) = delete;
    };
};

} // namespace lk::ui
