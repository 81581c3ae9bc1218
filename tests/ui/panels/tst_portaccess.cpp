// Permission for serial ports: the group and command from os-release (ID, then ID_LIKE),
// the dialog that shows the command with a copy button, and the connection bar offering it
// after a port was refused.

#include <panels/ConnectionBar.h>
#include <panels/PortAccessDialog.h>
#include <panels/SerialGroupAdvice.h>

#include <QtGui/QClipboard>
#include <QtTest/QtTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QToolButton>

using lk::ui::ConnectionBar;
using lk::ui::PortAccessDialog;
using lk::ui::SerialGroupAdvice;
using Kind = lk::transport::TransportError::Kind;

namespace {
lk::transport::TransportError error(Kind kind)
{
    lk::transport::TransportError e;
    e.kind = kind;
    e.message = QStringLiteral("from the driver");
    return e;
}
} // namespace

class tst_PortAccess : public QObject {
    Q_OBJECT
private slots:
    void advice_data();
    void advice();
    void parseOsRelease();
    void commandAndExplanation();
    void dialogCopiesTheCommand();
    void barOffersHelpAfterPermissionDenied();
    void barIgnoresOtherErrors();
};

void tst_PortAccess::advice_data()
{
    QTest::addColumn<QByteArray>("osRelease");
    QTest::addColumn<QString>("group");
    QTest::addColumn<bool>("known");
    QTest::addColumn<QString>("distribution");
    QTest::newRow("debian") << QByteArray("PRETTY_NAME=\"Debian GNU/Linux 12 (bookworm)\"\n"
                                          "NAME=\"Debian GNU/Linux\"\nID=debian\n")
                            << "dialout" << true << "Debian GNU/Linux 12 (bookworm)";
    QTest::newRow("ubuntu") << QByteArray("NAME=\"Ubuntu\"\nID=ubuntu\nID_LIKE=debian\n"
                                          "PRETTY_NAME=\"Ubuntu 24.04 LTS\"\n")
                            << "dialout" << true << "Ubuntu 24.04 LTS";
    QTest::newRow("mint via ID_LIKE") << QByteArray("ID=linuxmint\nID_LIKE=\"ubuntu debian\"\n"
                                                    "NAME=\"Linux Mint\"\n")
                                      << "dialout" << true << "Linux Mint";
    QTest::newRow("arch") << QByteArray("NAME=\"Arch Linux\"\nPRETTY_NAME=\"Arch Linux\"\n"
                                        "ID=arch\n")
                          << "uucp" << true << "Arch Linux";
    QTest::newRow("manjaro via ID_LIKE")
        << QByteArray("ID=manjaro\nID_LIKE=arch\n") << "uucp" << true << "manjaro";
    QTest::newRow("fedora") << QByteArray("NAME=\"Fedora Linux\"\nID=fedora\n") << "dialout" << true
                            << "Fedora Linux";
    QTest::newRow("single quotes, upper case")
        << QByteArray("ID='Arch'\nNAME='Arch Linux'\n") << "uucp" << true << "Arch Linux";
    QTest::newRow("unknown") << QByteArray("ID=plan9\nNAME=\"Plan 9\"\n") << "dialout" << false
                             << "Plan 9";
    QTest::newRow("empty") << QByteArray() << "dialout" << false << "";
}

void tst_PortAccess::advice()
{
    QFETCH(QByteArray, osRelease);
    QFETCH(QString, group);
    QFETCH(bool, known);
    QFETCH(QString, distribution);
    const SerialGroupAdvice a = SerialGroupAdvice::fromOsRelease(osRelease);
    QCOMPARE(a.group, group);
    QCOMPARE(a.known, known);
    QCOMPARE(a.distribution, distribution);
}

void tst_PortAccess::parseOsRelease()
{
    const auto f = SerialGroupAdvice::parseOsRelease(
        "# a comment\n\n  ID=debian  \nNAME=\"Say \\\"hi\\\" \\$HOME\"\nnot a field\n=x\n");
    QCOMPARE(f.value(QStringLiteral("ID")), QStringLiteral("debian"));
    QCOMPARE(f.value(QStringLiteral("NAME")), QStringLiteral("Say \"hi\" $HOME"));
    QCOMPARE(f.size(), 2);
}

void tst_PortAccess::commandAndExplanation()
{
    const SerialGroupAdvice arch = SerialGroupAdvice::fromOsRelease("ID=arch\nNAME=Arch\n");
    QCOMPARE(arch.command(), QStringLiteral("sudo usermod -aG uucp $USER"));
    QVERIFY(arch.explanation().contains(QStringLiteral("log out and back in")));
    QVERIFY(arch.explanation().contains(QStringLiteral("Arch")));
    const SerialGroupAdvice unknown = SerialGroupAdvice::fromOsRelease("ID=plan9\n");
    QCOMPARE(unknown.command(), QStringLiteral("sudo usermod -aG dialout $USER"));
    QVERIFY(unknown.explanation().contains(QStringLiteral("usually")));
}

void tst_PortAccess::dialogCopiesTheCommand()
{
    PortAccessDialog dialog(QStringLiteral("/dev/ttyUSB0"),
                            SerialGroupAdvice::fromOsRelease("ID=ubuntu\nNAME=Ubuntu\n"));
    QCOMPARE(dialog.command(), QStringLiteral("sudo usermod -aG dialout $USER"));
    QVERIFY(dialog.windowTitle().contains(QStringLiteral("/dev/ttyUSB0")));
    QGuiApplication::clipboard()->clear();
    QTest::mouseClick(dialog.copyButton(), Qt::LeftButton);
    QCOMPARE(QGuiApplication::clipboard()->text(), dialog.command());
}

void tst_PortAccess::barOffersHelpAfterPermissionDenied()
{
    ConnectionBar bar;
    bar.setPortLister([] { return QList<lk::ui::PortEntry>{}; });
    lk::ui::ConnectionChoice c;
    c.kind = lk::ui::ConnectionChoice::Kind::Serial;
    c.port = QStringLiteral("/dev/ttyACM3");
    bar.setChoice(c);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    QVERIFY(!bar.accessHelpButton()->isVisible());

    bar.showPortError(error(Kind::PermissionDenied));
    QVERIFY(bar.accessHelpButton()->isVisible());
    QTest::mouseClick(bar.accessHelpButton(), Qt::LeftButton);
    auto *dialog = bar.findChild<PortAccessDialog *>();
    QVERIFY(dialog);
    QTRY_VERIFY(dialog->isVisible());
    QVERIFY(dialog->windowTitle().contains(QStringLiteral("/dev/ttyACM3")));
    QVERIFY(dialog->command().startsWith(QStringLiteral("sudo usermod -aG ")));
    dialog->close();

    lk::bus::ConnectionStatus open;
    open.state = lk::transport::Transport::State::Open;
    bar.setConnectionStatus(open);
    QVERIFY(!bar.accessHelpButton()->isVisible());
}

void tst_PortAccess::barIgnoresOtherErrors()
{
    ConnectionBar bar;
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    for (Kind k :
         {Kind::NoSuchPort, Kind::PortBusy, Kind::Unplugged, Kind::BadSettings, Kind::IoError})
        bar.showPortError(error(k));
    QVERIFY(!bar.accessHelpButton()->isVisible());
}

QTEST_MAIN(tst_PortAccess)
#include "tst_portaccess.moc"
