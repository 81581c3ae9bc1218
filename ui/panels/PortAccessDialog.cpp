#include "PortAccessDialog.h"

#include <QtGui/QClipboard>
#include <QtGui/QFontDatabase>
#include <QtGui/QGuiApplication>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

PortAccessDialog::PortAccessDialog(const QString &port, const SerialGroupAdvice &advice,
                                   QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("portAccessDialog"));
    setWindowTitle(tr("No permission for %1").arg(port));
    auto *layout = new QVBoxLayout(this);
    auto *what = new QLabel(tr("lkstudio may not open %1: your user is not in the group that "
                               "owns serial ports.")
                                .arg(port),
                            this);
    what->setWordWrap(true);
    auto *how = new QLabel(advice.explanation(), this);
    how->setObjectName(QStringLiteral("explanation"));
    how->setWordWrap(true);

    m_command = new QLineEdit(advice.command(), this);
    m_command->setObjectName(QStringLiteral("command"));
    m_command->setReadOnly(true);
    m_command->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_command->setMinimumWidth(m_command->fontMetrics().horizontalAdvance(advice.command()) + 24);
    m_copy = new QPushButton(tr("Copy"), this);
    m_copy->setObjectName(QStringLiteral("copyCommand"));
    connect(m_copy, &QPushButton::clicked, this, [this] {
        QGuiApplication::clipboard()->setText(m_command->text());
        m_copy->setText(tr("Copied"));
    });
    auto *row = new QHBoxLayout;
    row->addWidget(m_command, 1);
    row->addWidget(m_copy);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(what);
    layout->addWidget(how);
    layout->addLayout(row);
    layout->addWidget(buttons);
}

QString PortAccessDialog::command() const
{
    return m_command->text();
}

} // namespace lk::ui
