// What the stop report and the link-loss warnings say a drive was last told
// (CommandedMotion::describe): every value with its unit, an MS drive's power too.

#include <main/CommandedMotion.h>
#include <panels/Format.h>

#include <protocol/RequestBuilder.h>

#include <QtTest/QtTest>

Q_DECLARE_METATYPE(lk::protocol::Request)

using lk::ui::CommandedMotion;
namespace build = lk::protocol::build;

class tst_CommandedMotion : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QLocale::setDefault(QLocale::c()); }
    void describesWithUnits_data();
    void describesWithUnits();
};

void tst_CommandedMotion::describesWithUnits_data()
{
    QTest::addColumn<lk::protocol::Request>("request");
    QTest::addColumn<QString>("text");
    QTest::newRow("power 0") << *build::openLoop(1, 0).request << "open-loop power 0 rel.";
    QTest::newRow("power -300") << *build::openLoop(1, -300).request << "open-loop power -300 rel.";
    QTest::newRow("speed") << *build::speed(1, 360).request << "speed 360 dps";
    QTest::newRow("torque") << *build::torque(1, 0.5, {}).request << "torque 0.5 A";
    QTest::newRow("position") << *build::multiPosition(1, 90).request << "position 90\u00b0";
}

void tst_CommandedMotion::describesWithUnits()
{
    QFETCH(lk::protocol::Request, request);
    QFETCH(QString, text);
    QCOMPARE(CommandedMotion::describe(request), text);
}

QTEST_MAIN(tst_CommandedMotion)
#include "tst_commandedmotion.moc"
