#include "ParametersView.h"

#include "FleetGrid.h"
#include "FleetWriteDialog.h"

#include <bus/BusSession.h>
#include <fleet/BackupFile.h>
#include <fleet/IdMap.h>

#include <QtCore/QDir>
#include <QtCore/QStandardPaths>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QProgressBar>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTableWidget>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

ParametersView::ParametersView(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    auto *top = new QHBoxLayout;
    m_read = new QPushButton(tr("Read all"), this);
    m_read->setObjectName(QStringLiteral("readAll"));
    m_read->setToolTip(tr("Reads every parameter of every drive found, one drive after "
                          "another. Nothing is written."));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("cancelRead"));
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("readProgress"));
    m_reference = new QComboBox(this);
    m_reference->setObjectName(QStringLiteral("reference"));
    m_reference->setToolTip(tr("Cells that differ from this drive are marked"));
    m_onlyDiffering = new QCheckBox(tr("Only rows that differ"), this);
    m_onlyDiffering->setObjectName(QStringLiteral("onlyDiffering"));
    top->addWidget(m_read);
    top->addWidget(m_cancel);
    top->addWidget(m_progress, 1);
    top->addWidget(new QLabel(tr("Reference:"), this));
    top->addWidget(m_reference);
    top->addWidget(m_onlyDiffering);
    m_table = new QTableWidget(this);
    m_table->setObjectName(QStringLiteral("parameters"));
    auto *bottom = new QHBoxLayout;
    m_backup = new QPushButton(tr("Back up..."), this);
    m_backup->setObjectName(QStringLiteral("backup"));
    m_backup->setToolTip(tr("Saves the values read into one bus backup file"));
    m_restore = new QPushButton(tr("Restore..."), this);
    m_restore->setObjectName(QStringLiteral("restore"));
    m_restore->setToolTip(tr("Writes a backup's values onto the drives of the same IDs: the "
                             "targets are read and the changes shown first"));
    m_idMap = new QLineEdit(this);
    m_idMap->setObjectName(QStringLiteral("idMap"));
    m_idMap->setPlaceholderText(tr("ID map, e.g. 3:5"));
    m_idMap->setToolTip(tr("Restore the backup's drive 3 onto drive 5 (a replaced drive). With "
                           "a map, only the mapped drives are restored."));
    m_clone = new QPushButton(tr("Clone reference..."), this);
    m_clone->setObjectName(QStringLiteral("cloneReference"));
    m_clone->setToolTip(tr("Writes the reference drive's values onto the other drives read: "
                           "the targets are read and the changes shown first"));
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);
    bottom->addWidget(m_backup);
    bottom->addWidget(m_restore);
    bottom->addWidget(m_idMap);
    bottom->addWidget(m_clone);
    bottom->addWidget(m_status, 1);
    layout->addLayout(top);
    layout->addWidget(m_table, 1);
    layout->addLayout(bottom);

    connect(m_read, &QPushButton::clicked, this, &ParametersView::readAll);
    connect(m_cancel, &QPushButton::clicked, this, &ParametersView::cancelRead);
    connect(m_reference, &QComboBox::currentIndexChanged, this, &ParametersView::refill);
    connect(m_onlyDiffering, &QCheckBox::toggled, this, &ParametersView::refill);
    connect(m_backup, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Back up the bus"), QString(),
                                                          tr("Bus backup (*.json)"));
        if (path.isEmpty())
            return;
        const QString why = backupTo(path);
        m_status->setText(why.isEmpty() ? tr("Backed up into %1.").arg(path) : why);
    });
    connect(m_restore, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Restore a bus backup"),
                                                          QString(), tr("Bus backup (*.json)"));
        if (!path.isEmpty())
            restoreFrom(path);
    });
    connect(m_clone, &QPushButton::clicked, this, &ParametersView::cloneReference);
    updateActions();
}

void ParametersView::setSession(bus::BusSession *session)
{
    m_session = session;
    delete m_reader;
    m_reader = new fleet::FleetReader(session, this);
    connect(m_reader, &fleet::FleetReader::driveRead, this, &ParametersView::onDriveRead);
    connect(m_reader, &fleet::FleetReader::finished, this, &ParametersView::onReadFinished);
    updateActions();
}

void ParametersView::setConnected(bool connected)
{
    m_connected = connected;
    if (!connected && m_reader && m_reader->running())
        m_reader->cancel();
    updateActions();
}

void ParametersView::setDrives(const QVector<int> &ids)
{
    m_ids = ids;
    updateActions();
}

void ParametersView::readAll()
{
    if (!m_reader || !m_connected || m_ids.isEmpty())
        return;
    m_snapshots.clear();
    m_progress->setRange(0, int(m_ids.size()));
    m_progress->setValue(0);
    m_status->setText(tr("Reading %n drive(s) ...", nullptr, int(m_ids.size())));
    m_reader->start(m_ids);
    updateActions();
}

void ParametersView::cancelRead()
{
    if (m_reader)
        m_reader->cancel();
}

void ParametersView::onDriveRead(const fleet::DriveSnapshot &snapshot, int done, int)
{
    m_snapshots << snapshot;
    m_progress->setValue(done);
    refill();
}

void ParametersView::onReadFinished()
{
    int failed = 0;
    for (const fleet::DriveSnapshot &d : std::as_const(m_snapshots))
        failed += d.complete() && d.failure.isEmpty() ? 0 : 1;
    QString text = m_reader->cancelled()
                       ? tr("Cancelled after %n drive(s).", nullptr, int(m_snapshots.size()))
                       : tr("%n drive(s) read.", nullptr, int(m_snapshots.size()));
    if (failed > 0)
        text += QLatin1Char(' ') + tr("%n could not be read completely: their missing values "
                                      "show as unknown.",
                                      nullptr, failed);
    m_status->setText(text);
    // The reference list follows the drives read, keeping the one chosen.
    const int chosen = m_reference->currentData().toInt();
    const QSignalBlocker block(m_reference);
    m_reference->clear();
    for (const fleet::DriveSnapshot &d : std::as_const(m_snapshots)) {
        if (d.complete())
            m_reference->addItem(tr("Drive %1").arg(d.id()), d.id());
    }
    const int at = m_reference->findData(chosen);
    m_reference->setCurrentIndex(at >= 0 ? at : 0);
    refill();
    updateActions();
}

void ParametersView::refill()
{
    FleetGrid::fill(m_table, m_snapshots, m_reference->currentData().toInt(),
                    m_onlyDiffering->isChecked());
}

void ParametersView::updateActions()
{
    const bool reading = m_reader && m_reader->running();
    const bool canSend = m_connected && m_session && !reading;
    m_read->setEnabled(canSend && !m_ids.isEmpty());
    m_cancel->setEnabled(reading);
    m_backup->setEnabled(!reading && !m_snapshots.isEmpty());
    m_restore->setEnabled(canSend);
    m_clone->setEnabled(canSend && m_reference->count() > 0 && m_snapshots.size() > 1);
}

QString ParametersView::backupTo(const QString &path) const
{
    fleet::BackupFile file;
    file.savedAt = QDateTime::currentDateTimeUtc();
    file.drives = m_snapshots;
    return file.save(path);
}

QString ParametersView::undoPath()
{
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
                        QStringLiteral("/undo");
    QDir().mkpath(dir);
    return dir + QStringLiteral("/undo-%1.json")
                     .arg(QDateTime::currentDateTimeUtc().toString(
                         QStringLiteral("yyyyMMdd-HHmmss-zzz")));
}

FleetWriteDialog *ParametersView::openWriteDialog(const QVector<fleet::FleetRestore::Job> &jobs,
                                                  const QString &title)
{
    auto *dialog = new FleetWriteDialog(m_session, jobs, title, undoPath(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

FleetWriteDialog *ParametersView::restoreFrom(const QString &path)
{
    record::ParameterFileError error;
    const std::optional<fleet::BackupFile> file = fleet::BackupFile::load(path, &error);
    if (!file) {
        m_status->setText(tr("%1 is refused, nothing was sent: %2")
                              .arg(path, fleet::BackupFile::errorText(error)));
        return nullptr;
    }
    QString why;
    const QString mapText = m_idMap->text().trimmed();
    const std::optional<QMap<int, int>> map =
        mapText.isEmpty() ? QMap<int, int>() : fleet::IdMap::parseMap(mapText, &why);
    if (!map) {
        m_status->setText(tr("The ID map is refused, nothing was sent: %1").arg(why));
        return nullptr;
    }
    QVector<fleet::FleetRestore::Job> jobs;
    for (const fleet::DriveSnapshot &d : file->drives) {
        if (map->isEmpty() || map->contains(d.id()))
            jobs << fleet::FleetRestore::Job{d, map->value(d.id(), d.id())};
    }
    if (jobs.isEmpty()) {
        m_status->setText(
            tr("%1 holds none of the drives of the ID map: nothing was sent.").arg(path));
        return nullptr;
    }
    return openWriteDialog(jobs, tr("Restore %1").arg(QDir::toNativeSeparators(path)));
}

FleetWriteDialog *ParametersView::cloneReference()
{
    const int reference = m_reference->currentData().toInt();
    const fleet::DriveSnapshot *source = nullptr;
    for (const fleet::DriveSnapshot &d : std::as_const(m_snapshots)) {
        if (d.id() == reference)
            source = &d;
    }
    if (!source)
        return nullptr;
    QVector<fleet::FleetRestore::Job> jobs;
    for (const fleet::DriveSnapshot &d : std::as_const(m_snapshots)) {
        if (d.id() != reference)
            jobs << fleet::FleetRestore::Job{*source, d.id()};
    }
    return openWriteDialog(jobs, tr("Clone drive %1").arg(reference));
}

} // namespace lk::ui
