<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>lk::bus::WireExchange</name>
    <message numerus="yes">
        <source>no reply to %1 after %n attempt(s)</source>
        <translation>
            <numerusform>no reply to %1 after %n attempt</numerusform>
            <numerusform>no reply to %1 after %n attempts</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::ControlCommandBox</name>
    <message numerus="yes">
        <source>%n drives are selected: every command here acts on %1 only.</source>
        <translation>
            <numerusform>%n drive is selected: every command here acts on %1 only.</numerusform>
            <numerusform>%n drives are selected: every command here acts on %1 only.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveInfoView</name>
    <message numerus="yes">
        <source>Bus report gathered: %n drive(s).</source>
        <translation>
            <numerusform>Bus report gathered: one drive.</numerusform>
            <numerusform>Bus report gathered: %n drives.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::DriveTree</name>
    <message numerus="yes">
        <source>%n drive(s)</source>
        <translation>
            <numerusform>%n drive</numerusform>
            <numerusform>%n drives</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::EmergencyStopReport</name>
    <message numerus="yes">
        <source>Emergency stop: Motor Off sent to %n ID(s); no drive answered.</source>
        <translation>
            <numerusform>Emergency stop: Motor Off sent to %n ID; no drive answered.</numerusform>
            <numerusform>Emergency stop: Motor Off sent to %n IDs; no drive answered.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Emergency stop: Motor Off sent to %n ID(s); acknowledged by drive(s) %1.</source>
        <translation>
            <numerusform>Emergency stop: Motor Off sent to %n ID; acknowledged by drive(s) %1.</numerusform>
            <numerusform>Emergency stop: Motor Off sent to %n IDs; acknowledged by drive(s) %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::FleetWriteDialog</name>
    <message numerus="yes">
        <source>%n value(s) change</source>
        <translation>
            <numerusform>%n value changes</numerusform>
            <numerusform>%n values change</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::GainSearchViewOutcome</name>
    <message numerus="yes">
        <source>%n candidate(s) tried in %1 s; the best is in bold, Write to RAM tries it. Nothing else was kept.</source>
        <translation>
            <numerusform>%n candidate tried in %1 s; the best is in bold, Write to RAM tries it. Nothing else was kept.</numerusform>
            <numerusform>%n candidates tried in %1 s; the best is in bold, Write to RAM tries it. Nothing else was kept.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n candidate(s) tried in %1 s; none stayed within the bounds.</source>
        <translation>
            <numerusform>%n candidate tried in %1 s; none stayed within the bounds.</numerusform>
            <numerusform>%n candidates tried in %1 s; none stayed within the bounds.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::OverviewPanel</name>
    <message numerus="yes">
        <source>%n drive(s) on the bus</source>
        <translation>
            <numerusform>%n drive on the bus</numerusform>
            <numerusform>%n drives on the bus</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) with error flags</source>
        <translation>
            <numerusform>%n drive with error flags</numerusform>
            <numerusform>%n drives with error flags</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::ParametersView</name>
    <message numerus="yes">
        <source>Reading %n drive(s) ...</source>
        <translation>
            <numerusform>Reading %n drive ...</numerusform>
            <numerusform>Reading %n drives ...</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Cancelled after %n drive(s).</source>
        <translation>
            <numerusform>Cancelled after %n drive.</numerusform>
            <numerusform>Cancelled after %n drives.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) read.</source>
        <translation>
            <numerusform>%n drive read.</numerusform>
            <numerusform>%n drives read.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n could not be read completely: their missing values show as unknown.</source>
        <translation>
            <numerusform>%n could not be read completely: its missing values show as unknown.</numerusform>
            <numerusform>%n could not be read completely: their missing values show as unknown.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::RecordingController</name>
    <message numerus="yes">
        <source>Save the last %n minute(s)</source>
        <translation>
            <numerusform>Save the last %n minute</numerusform>
            <numerusform>Save the last %n minutes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Black box saved after %1: the last %n minute(s) of the link are in %2</source>
        <translation>
            <numerusform>Black box saved after %1: the last %n minute of the link is in %2</numerusform>
            <numerusform>Black box saved after %1: the last %n minutes of the link are in %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s) written to %1 as a candump log.</source>
        <translation>
            <numerusform>%n frame written to %1 as a candump log.</numerusform>
            <numerusform>%n frames written to %1 as a candump log.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::ScanControls</name>
    <message numerus="yes">
        <source>ID %1 at %2 baud · %n drive(s) found · about %3 left</source>
        <translation>
            <numerusform>ID %1 at %2 baud · %n drive found · about %3 left</numerusform>
            <numerusform>ID %1 at %2 baud · %n drives found · about %3 left</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Scan cancelled after %1: %n drive(s) found</source>
        <translation>
            <numerusform>Scan cancelled after %1: %n drive found</numerusform>
            <numerusform>Scan cancelled after %1: %n drives found</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Scan done in %1: %n drive(s) found</source>
        <translation>
            <numerusform>Scan done in %1: %n drive found</numerusform>
            <numerusform>Scan done in %1: %n drives found</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>ID %1 at %2 · %n drive(s) found · about %3 left</source>
        <translation>
            <numerusform>ID %1 at %2 · %n drive found · about %3 left</numerusform>
            <numerusform>ID %1 at %2 · %n drives found · about %3 left</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::StepRunsModel</name>
    <message numerus="yes">
        <source>Best of the %n comparable run(s) shown (same loop and unit).</source>
        <translation>
            <numerusform>Best of the %n comparable run shown (same loop and unit).</numerusform>
            <numerusform>Best of the %n comparable runs shown (same loop and unit).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lk::ui::StepRunsView</name>
    <message numerus="yes">
        <source>%n run(s) of the other loop hidden: the overlay shows one loop at a time.</source>
        <translation>
            <numerusform>%n run of the other loop hidden: the overlay shows one loop at a time.</numerusform>
            <numerusform>%n runs of the other loop hidden: the overlay shows one loop at a time.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Saved %n run(s) to %1.</source>
        <translation>
            <numerusform>Saved %n run to %1.</numerusform>
            <numerusform>Saved %n runs to %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Added %n run(s) from %1.</source>
        <translation>
            <numerusform>Added %n run from %1.</numerusform>
            <numerusform>Added %n runs from %1.</numerusform>
        </translation>
    </message>
</context>
</TS>
