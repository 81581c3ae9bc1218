#include "SendBlockedTips.h"

#include <QtWidgets/QAbstractButton>
#include <QtWidgets/QWidget>

namespace lk::ui {

namespace {
// The button's own tooltip, kept while the reason stands in front of it.
const char kOwnTip[] = "lkOwnToolTip";
} // namespace

void SendBlockedTips::apply(QWidget *root, const QString &reason)
{
    const auto buttons = root->findChildren<QAbstractButton *>();
    for (QAbstractButton *b : buttons)
        applyTo(b, reason);
}

void SendBlockedTips::applyTo(QAbstractButton *b, const QString &reason)
{
    const QVariant own = b->property(kOwnTip);
    if (reason.isEmpty() || b->isEnabled()) {
        if (own.isValid()) {
            b->setToolTip(own.toString());
            b->setProperty(kOwnTip, QVariant());
        }
        return;
    }
    const QString mine = own.isValid() ? own.toString() : b->toolTip();
    if (!own.isValid())
        b->setProperty(kOwnTip, mine);
    b->setToolTip(mine.isEmpty() ? reason : QStringLiteral("%1\n\n%2").arg(reason, mine));
}

} // namespace lk::ui
