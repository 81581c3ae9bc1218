#include "ConfirmDialog.h"

#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QStyle>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
ConfirmDialog::Policy &policySlot()
{
    static ConfirmDialog::Policy policy;
    return policy;
}
constexpr int kIconSize = 48;
constexpr int kTextWidth = 420;
} // namespace

ConfirmDialog::ConfirmDialog(const ConfirmRequest &request, QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("confirm_") + request.key);
    setWindowTitle(request.title);
    setModal(true);

    auto *icon = new QLabel(this);
    icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(kIconSize));
    icon->setAlignment(Qt::AlignTop);

    auto *question = new QLabel(request.question, this);
    question->setWordWrap(true);
    question->setMinimumWidth(kTextWidth);
    QFont bold = question->font();
    bold.setBold(true);
    question->setFont(bold);
    auto *reason = new QLabel(request.reason, this);
    reason->setObjectName(QStringLiteral("reason"));
    reason->setWordWrap(true);
    reason->setMinimumWidth(kTextWidth);

    auto *buttons = new QDialogButtonBox(this);
    QPushButton *accept = buttons->addButton(request.acceptText, QDialogButtonBox::AcceptRole);
    QPushButton *cancel = buttons->addButton(QDialogButtonBox::Cancel);
    accept->setAutoDefault(false);
    cancel->setDefault(true); // Enter must never write flash by accident
    cancel->setFocus();
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *text = new QVBoxLayout;
    text->addWidget(question);
    text->addWidget(reason);
    text->addStretch();
    auto *top = new QHBoxLayout;
    top->addWidget(icon);
    top->addLayout(text, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(buttons);
}

bool ConfirmDialog::ask(QWidget *parent, const ConfirmRequest &request)
{
    if (policySlot())
        return policySlot()(request);
    ConfirmDialog dialog(request, parent);
    return dialog.exec() == QDialog::Accepted;
}

bool ConfirmDialog::askUnchanged(QWidget *parent, const ConfirmRequest &request,
                                 const std::function<bool()> &unchanged, QString *why,
                                 bool *changed)
{
    const bool yes = ask(parent, request);
    *changed = yes && !unchanged();
    if (*changed)
        *why = tr("The drive or the connection changed: nothing was sent.");
    else if (!yes)
        *why = tr("Cancelled: nothing was sent.");
    return yes && !*changed;
}

void ConfirmDialog::setPolicy(Policy policy)
{
    policySlot() = std::move(policy);
}

} // namespace lk::ui
