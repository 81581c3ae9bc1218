#include "FileDialogs.h"

#include <QtCore/QDir>
#include <QtCore/QFileInfo>
#include <QtCore/QRegularExpression>
#include <QtCore/QStandardPaths>
#include <QtWidgets/QFileDialog>

namespace lk::ui {

namespace {
FileDialogs::FolderMemory &memory()
{
    static FileDialogs::FolderMemory m;
    return m;
}
} // namespace

void FileDialogs::setFolderMemory(FolderMemory m)
{
    memory() = std::move(m);
}

QString FileDialogs::purposeKey(Purpose purpose)
{
    switch (purpose) {
    case Purpose::PlotCsv:
        return QStringLiteral("plotCsv");
    case Purpose::PlotImage:
        return QStringLiteral("plotImage");
    case Purpose::Traffic:
        return QStringLiteral("traffic");
    case Purpose::Parameters:
        return QStringLiteral("parameters");
    case Purpose::BusReport:
        return QStringLiteral("busReport");
    case Purpose::StepRuns:
        return QStringLiteral("stepRuns");
    }
    return QStringLiteral("other");
}

QString FileDialogs::suggestedName(const QString &what, const QVector<int> &ids,
                                   const QDateTime &when, const QString &suffix)
{
    static const QRegularExpression unsafe(QStringLiteral("[^A-Za-z0-9._+-]+"));
    QStringList parts{QStringLiteral("lk")};
    for (int id : ids)
        parts << QStringLiteral("id%1").arg(id);
    QString tidy = what;
    tidy.replace(unsafe, QStringLiteral("-"));
    parts << tidy << when.toString(QStringLiteral("yyyy-MM-dd-HHmm"));
    parts.removeAll(QString());
    return parts.join(QLatin1Char('-')) + QLatin1Char('.') + suffix;
}

QString FileDialogs::startFolder(Purpose purpose)
{
    if (memory().folder) {
        const QString folder = memory().folder(purposeKey(purpose));
        if (!folder.isEmpty() && QFileInfo(folder).isDir())
            return folder;
    }
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return documents.isEmpty() || !QFileInfo(documents).isDir() ? QDir::homePath() : documents;
}

void FileDialogs::remember(Purpose purpose, const QString &chosenFile)
{
    if (memory().setFolder && !chosenFile.isEmpty())
        memory().setFolder(purposeKey(purpose), QFileInfo(chosenFile).absolutePath());
}

QString FileDialogs::saveFile(QWidget *parent, Purpose purpose, const QString &caption,
                              const QString &fileName, const QString &filter)
{
    const QString start = QDir(startFolder(purpose)).filePath(fileName);
    const QString chosen = QFileDialog::getSaveFileName(parent, caption, start, filter);
    remember(purpose, chosen);
    return chosen;
}

QString FileDialogs::openFile(QWidget *parent, Purpose purpose, const QString &caption,
                              const QString &filter)
{
    const QString chosen =
        QFileDialog::getOpenFileName(parent, caption, startFolder(purpose), filter);
    remember(purpose, chosen);
    return chosen;
}

} // namespace lk::ui
