#include "AboutDialog.h"

#include "DiagnosticsReport.h"

#include <QtGui/QClipboard>
#include <QtGui/QGuiApplication>
#include <QtGui/QIcon>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

namespace {
constexpr int kIconSize = 64;
const char kLicenceUrl[] = "https://www.gnu.org/licenses/gpl-3.0.html";
const char kLicenceId[] = "GPL-3.0-or-later";
} // namespace

AboutDialog::AboutDialog(std::function<QString()> diagnostics, QWidget *parent)
    : QDialog(parent), m_diagnostics(std::move(diagnostics))
{
    setObjectName(QStringLiteral("aboutDialog"));
    setWindowTitle(tr("About LK Servo Studio"));
    const DiagnosticsInfo info = DiagnosticsReport::systemInfo();

    auto *icon = new QLabel(this);
    icon->setPixmap(QIcon(QStringLiteral(":/icons/lkstudio.svg")).pixmap(kIconSize, kIconSize));
    icon->setAlignment(Qt::AlignTop);
    auto *title = new QLabel(
        tr("<h2>LK Servo Studio %1</h2><p>Tuning and diagnostics for LK-TECH MS/MF/MG/MH servo "
           "drives on RS485 (protocols V2.3 and V2.35). Esc sends Motor Off to every drive from "
           "anywhere "
           "in the program.</p>")
            .arg(info.programVersion.toHtmlEscaped()),
        this);
    title->setWordWrap(true);

    m_versions = new QLabel(this);
    m_versions->setObjectName(QStringLiteral("versions"));
    m_versions->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_versions->setText(
        tr("Qt %1 (built with %2), platform %3\n%4\n%5 (%6)")
            .arg(info.qtRuntime, info.qtBuild, info.platform, info.os, info.kernel, info.cpu));

    m_licence = new QLabel(this);
    m_licence->setObjectName(QStringLiteral("licence"));
    m_licence->setWordWrap(true);
    m_licence->setOpenExternalLinks(true);
    m_licence->setText(
        tr("<p>Licence: <a href=\"%1\">%2</a>. LK Servo Studio is free software: you may "
           "redistribute and modify it under the terms of the GNU General Public License, "
           "version 3 or any later version. It comes with ABSOLUTELY NO WARRANTY.</p>")
            .arg(QLatin1String(kLicenceUrl), QLatin1String(kLicenceId)));

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_copy = buttons->addButton(tr("Copy diagnostics"), QDialogButtonBox::ActionRole);
    m_copy->setObjectName(QStringLiteral("copyDiagnostics"));
    m_copy->setToolTip(tr("Copy versions, port, adapter, bus statistics and recent errors to "
                          "the clipboard, for a bug report"));
    connect(m_copy, &QPushButton::clicked, this, [this] {
        QGuiApplication::clipboard()->setText(m_diagnostics());
        m_copy->setText(tr("Copied"));
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *grid = new QGridLayout;
    grid->addWidget(icon, 0, 0, 3, 1);
    grid->addWidget(title, 0, 1);
    grid->addWidget(m_versions, 1, 1);
    grid->addWidget(m_licence, 2, 1);
    grid->setColumnStretch(1, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(grid);
    layout->addWidget(buttons);
    setMinimumWidth(520);
}

QString AboutDialog::versionsText() const
{
    return m_versions->text();
}

QString AboutDialog::licenceText() const
{
    return m_licence->text();
}

} // namespace lk::ui
