<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>kerf::ui::CycleCatalogueDialog</name>
    <message>
        <source>There is no cycle %1</source>
        <translation>Es gibt keinen Zyklus %1</translation>
    </message>
    <message>
        <source>Cycle definition</source>
        <translation>Zyklusdefinition</translation>
    </message>
    <message>
        <source>Cycle number</source>
        <translation>Zyklusnummer</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>kerf::ui::CycleDialog</name>
    <message>
        <source>Cycle definition</source>
        <translation>Zyklusdefinition</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FagorCycleDialog</name>
    <message>
        <source>Canned cycle</source>
        <translation>Festzyklus</translation>
    </message>
    <message>
        <source>* required</source>
        <translation>* Pflichtangabe</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FagorTableModel</name>
    <message>
        <source>Key</source>
        <translation>Schlüssel</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FileManager</name>
    <message>
        <source>All files</source>
        <translation>Alle Dateien</translation>
    </message>
    <message>
        <source>Programs (.H .I .PIT)</source>
        <translation>Programme (.H .I .PIT)</translation>
    </message>
    <message>
        <source>NC root: %1</source>
        <translation>NC-Verzeichnis: %1</translation>
    </message>
    <message>
        <source>Recent files</source>
        <translation>Zuletzt gewählte Dateien</translation>
    </message>
    <message>
        <source>File manager</source>
        <translation>Datei-Verwaltung</translation>
    </message>
    <message>
        <source>Copy %1 to:</source>
        <translation>%1 kopieren nach:</translation>
    </message>
    <message>
        <source>Copied to %1</source>
        <translation>Kopiert nach %1</translation>
    </message>
    <message>
        <source>Move %1 to folder:</source>
        <translation>%1 verschieben in Verzeichnis:</translation>
    </message>
    <message>
        <source>New name for %1:</source>
        <translation>Neuer Name für %1:</translation>
    </message>
    <message>
        <source>Delete %1?</source>
        <translation>%1 löschen?</translation>
    </message>
    <message>
        <source>Name of the new folder:</source>
        <translation>Name des neuen Verzeichnisses:</translation>
    </message>
    <message>
        <source>Tables (.T .TCH .PR .D .PNT .TP .TAB)</source>
        <translation>Tabellen (.T .TCH .PR .D .PNT .TP .TAB)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FindBar</name>
    <message>
        <source>Find</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <source>Replace with</source>
        <translation>Ersetzen durch</translation>
    </message>
    <message>
        <source>Match case</source>
        <translation>Groß-/Kleinschreibung</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>Vorheriges</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Nächstes</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Ersetzen</translation>
    </message>
    <message>
        <source>Replace all</source>
        <translation>Alle ersetzen</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Nicht gefunden</translation>
    </message>
    <message numerus="yes">
        <source>%n replaced</source>
        <translation>
            <numerusform>%n ersetzt</numerusform>
            <numerusform>%n ersetzt</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>kerf::ui::FkSketchView</name>
    <message>
        <source>Contour</source>
        <translation>Kontur</translation>
    </message>
    <message>
        <source>FK element determined</source>
        <translation>FK-Element bestimmt</translation>
    </message>
    <message>
        <source>FK element not determined</source>
        <translation>FK-Element nicht bestimmt</translation>
    </message>
    <message>
        <source>Solution %1 of %2</source>
        <translation>Lösung %1 von %2</translation>
    </message>
    <message>
        <source>Other solutions</source>
        <translation>Andere Lösungen</translation>
    </message>
    <message>
        <source>FK element with solution 1 assumed (no FSELECT)</source>
        <translation>FK-Element mit angenommener Lösung 1 (kein FSELECT)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::GraphicsPanel</name>
    <message>
        <source>The 3D graphics need a display</source>
        <translation>Die 3D-Grafik braucht eine Anzeige</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Machining time %1</source>
        <translation>Bearbeitungszeit %1</translation>
    </message>
    <message>
        <source>%1   %2 % done   %3 remaining</source>
        <translation>%1   %2 % erledigt   Restzeit %3</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineKeys</name>
    <message>
        <source>Machine on</source>
        <translation>Maschine ein</translation>
    </message>
    <message>
        <source>EMERGENCY STOP</source>
        <translation>NOT-AUS</translation>
    </message>
    <message>
        <source>Release EMERGENCY STOP</source>
        <translation>NOT-HALT entriegeln</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineSession</name>
    <message>
        <source>The machine is busy: stop the program or wait until the axes stand still</source>
        <translation>Die Maschine ist beschäftigt: das Programm anhalten oder warten, bis die Achsen stehen</translation>
    </message>
    <message>
        <source>The program has errors and cannot be started</source>
        <translation>Das Programm enthält Fehler und kann nicht gestartet werden</translation>
    </message>
    <message>
        <source>Program finished</source>
        <translation>Programm beendet</translation>
    </message>
    <message>
        <source>Program stopped</source>
        <translation>Programm angehalten</translation>
    </message>
    <message>
        <source>The preset could not be saved in PRESET.PR, so the next program uses the table&apos;s preset again: %1</source>
        <translation>Der Bezugspunkt konnte nicht in PRESET.PR gespeichert werden; das nächste Programm verwendet wieder den Bezugspunkt aus der Tabelle: %1</translation>
    </message>
    <message>
        <source>The machine is off (emergency stop or drive fault): switch it on with Machine on</source>
        <translation>Die Maschine ist aus (Not-Aus oder Antriebsfehler): mit Maschine ein einschalten</translation>
    </message>
    <message>
        <source>The machine is on already</source>
        <translation>Die Maschine ist bereits eingeschaltet</translation>
    </message>
    <message>
        <source>The axes are not referenced: run Home all in Manual operation first</source>
        <translation>Die Achsen sind nicht referenziert: zuerst in Manueller Betrieb Alle referenzieren ausführen</translation>
    </message>
    <message>
        <source>The emergency stop button is pressed: release it, then Machine on</source>
        <translation>Der NOT-HALT-Taster ist gedrückt: entriegeln, dann Maschine ein</translation>
    </message>
    <message>
        <source>Release the emergency stop button first</source>
        <translation>Zuerst den NOT-HALT-Taster entriegeln</translation>
    </message>
    <message>
        <source>The emergency stop chain is still open</source>
        <translation>Der NOT-HALT-Kreis ist noch offen</translation>
    </message>
    <message>
        <source>Probing: the stylus is deflected already</source>
        <translation>Antasten: der Taststift ist bereits ausgelenkt</translation>
    </message>
    <message>
        <source>Probing: no touch within %1 mm</source>
        <translation>Antasten: keine Berührung innerhalb von %1 mm</translation>
    </message>
    <message>
        <source>The basic rotation could not be saved in PRESET.PR: %1</source>
        <translation>Die Grunddrehung konnte nicht in PRESET.PR gespeichert werden: %1</translation>
    </message>
    <message>
        <source>The tool offset must be D1 to D255</source>
        <translation>Die Werkzeugkorrektur muss D1 bis D255 sein</translation>
    </message>
    <message>
        <source>Tool calibration: %1</source>
        <translation>Werkzeugkalibrierung: %1</translation>
    </message>
    <message>
        <source>Tool calibration works on X and Z only</source>
        <translation>Die Werkzeugkalibrierung gilt nur für X und Z</translation>
    </message>
    <message>
        <source>Tool %1: L = %2 mm</source>
        <translation>Werkzeug %1: L = %2 mm</translation>
    </message>
    <message>
        <source>The probing log TCHPRMAN.html could not be written: %1</source>
        <translation>Das Antastprotokoll TCHPRMAN.html konnte nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <source>Tool offset D%1: X = %2 mm (radius)</source>
        <translation>Werkzeugkorrektur D%1: X = %2 mm (Radius)</translation>
    </message>
    <message>
        <source>Tool offset D%1: Z = %2 mm</source>
        <translation>Werkzeugkorrektur D%1: Z = %2 mm</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MainWindow</name>
    <message>
        <source>%1 has unsaved changes from an earlier session: press &quot;Restore autosave&quot; to get them back</source>
        <translation>%1 hat ungespeicherte Änderungen aus einer früheren Sitzung: „Autosave wiederherstellen“ holt sie zurück</translation>
    </message>
    <message>
        <source>Kerf - %1</source>
        <translation>Kerf - %1</translation>
    </message>
    <message>
        <source>Programming station</source>
        <translation>Programmierplatz</translation>
    </message>
    <message>
        <source>Screen
layout</source>
        <translation>Bildschirm-
aufteilung</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Dateien</translation>
    </message>
    <message>
        <source>Tool
table</source>
        <translation>Werkzeug-
tabelle</translation>
    </message>
    <message>
        <source>Message
list</source>
        <translation>Meldungs-
liste</translation>
    </message>
    <message>
        <source>Clear
messages</source>
        <translation>Meldungen
löschen</translation>
    </message>
    <message>
        <source>Language
%1</source>
        <translation>Sprache
%1</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopieren</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Protect /
unprotect</source>
        <translation>Schützen /
freigeben</translation>
    </message>
    <message>
        <source>New
folder</source>
        <translation>Neues
Verzeichnis</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Insert
row</source>
        <translation>Zeile
einfügen</translation>
    </message>
    <message>
        <source>Delete
row</source>
        <translation>Zeile
löschen</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Find /
replace</source>
        <translation>Suchen /
ersetzen</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Renumber
blocks</source>
        <translation>Sätze neu
nummerieren</translation>
    </message>
    <message>
        <source>Check
program</source>
        <translation>Programm
prüfen</translation>
    </message>
    <message>
        <source>Restore
autosave</source>
        <translation>Autosave
wiederherstellen</translation>
    </message>
    <message>
        <source>Tables</source>
        <translation>Tabellen</translation>
    </message>
    <message>
        <source>MOD</source>
        <translation>MOD</translation>
    </message>
    <message>
        <source>No program is open: open one in Files</source>
        <translation>Kein Programm geöffnet: eines in Dateien öffnen</translation>
    </message>
    <message>
        <source>Machine
parameters</source>
        <translation>Maschinen-
parameter</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Speed
%1</source>
        <translation>Geschwindigkeit
%1</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>Zoom
+</source>
        <translation>Zoom
+</translation>
    </message>
    <message>
        <source>Zoom
-</source>
        <translation>Zoom
-</translation>
    </message>
    <message>
        <source>New
program</source>
        <translation>Neues
Programm</translation>
    </message>
    <message>
        <source>Go to
block</source>
        <translation>Gehe zu
Satz</translation>
    </message>
    <message>
        <source>Go to block</source>
        <translation>Gehe zu Satz</translation>
    </message>
    <message>
        <source>The program</source>
        <translation>Das Programm</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <source>A program is running. Stop it and quit?</source>
        <translation>Ein Programm läuft. Anhalten und beenden?</translation>
    </message>
    <message>
        <source>The spindle turns. Stop it and quit?</source>
        <translation>Die Spindel dreht. Anhalten und beenden?</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <source>Start at block</source>
        <translation>Start bei Satz</translation>
    </message>
    <message>
        <source>No user customisation program: %1 is not in the NC root</source>
        <translation>Kein Anwender-Anpassungsprogramm: %1 ist nicht im NC-Verzeichnis</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Anwender</translation>
    </message>
    <message>
        <source>Leave
user screen</source>
        <translation>Anwender-
bild verlassen</translation>
    </message>
    <message>
        <source>The program in the editor is protected: the block %1 of the user screen was not inserted</source>
        <translation>Das Programm im Editor ist geschützt: der Satz %1 des Anwenderbilds wurde nicht eingefügt</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MdiDialog</name>
    <message>
        <source>Positioning with MDI</source>
        <translation>Positionieren mit Handeingabe</translation>
    </message>
    <message>
        <source>Block (arrow keys: the blocks run before)</source>
        <translation>Satz (Pfeiltasten: die zuvor ausgeführten Sätze)</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MessagePanel</name>
    <message>
        <source>Severity</source>
        <translation>Schwere</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <source>No messages</source>
        <translation>Keine Meldungen</translation>
    </message>
    <message>
        <source>%1 - %2%3</source>
        <translation>%1 - %2%3</translation>
    </message>
    <message numerus="yes">
        <source> (%n more)</source>
        <translation>
            <numerusform> (%n weitere)</numerusform>
            <numerusform> (%n weitere)</numerusform>
        </translation>
    </message>
    <message>
        <source>Block</source>
        <translation>Satz</translation>
    </message>
    <message>
        <source>%1: </source>
        <translation>%1: </translation>
    </message>
</context>
<context>
    <name>kerf::ui::ModPage</name>
    <message>
        <source>MOD functions</source>
        <translation>MOD-Funktionen</translation>
    </message>
    <message>
        <source>Position display</source>
        <translation>Positions-Anzeige</translation>
    </message>
    <message>
        <source>Unit of the position display</source>
        <translation>Maßeinheit der Positions-Anzeige</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>Software: Kerf %1 (Qt %2)
Machine: %3</source>
        <translation>Software: Kerf %1 (Qt %2)
Maschine: %3</translation>
    </message>
    <message>
        <source>Kerf is free software: you may share and change it under the GNU General Public License, version 3 or later. It comes with no warranty.</source>
        <translation>Kerf ist freie Software: Sie dürfen sie unter der GNU General Public License, Version 3 oder später, weitergeben und verändern. Sie wird ohne jede Gewährleistung geliefert.</translation>
    </message>
</context>
<context>
    <name>kerf::ui::NewProgramDialog</name>
    <message>
        <source>New program</source>
        <translation>Neues Programm</translation>
    </message>
    <message>
        <source>Program name</source>
        <translation>Programmname</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Blank MIN %1</source>
        <translation>Rohteil MIN %1</translation>
    </message>
    <message>
        <source>Blank MAX %1</source>
        <translation>Rohteil MAX %1</translation>
    </message>
    <message>
        <source>Give the program a name without spaces or folders</source>
        <translation>Dem Programm einen Namen ohne Leerzeichen und Verzeichnisse geben</translation>
    </message>
    <message>
        <source>The blank&apos;s MIN point must lie below its MAX point on every axis</source>
        <translation>Der MIN-Punkt des Rohteils muss auf jeder Achse unter seinem MAX-Punkt liegen</translation>
    </message>
</context>
<context>
    <name>kerf::ui::OperatorInputDialog</name>
    <message>
        <source>Operator inputs</source>
        <translation>Bedienereingaben</translation>
    </message>
    <message>
        <source>The program reads these inputs: enter their values</source>
        <translation>Das Programm liest diese Eingaben: Werte eingeben</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Starten</translation>
    </message>
</context>
<context>
    <name>kerf::ui::OverrideControls</name>
    <message>
        <source>Feed</source>
        <translation>Vorschub</translation>
    </message>
    <message>
        <source>Rapid</source>
        <translation>Eilgang</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Spindel</translation>
    </message>
</context>
<context>
    <name>kerf::ui::PathFunctionDialog</name>
    <message>
        <source>Path function</source>
        <translation>Bahnfunktion</translation>
    </message>
</context>
<context>
    <name>kerf::ui::PositionDisplay</name>
    <message>
        <source>ACTL.</source>
        <translation>IST</translation>
    </message>
    <message>
        <source>NOML.</source>
        <translation>SOLL</translation>
    </message>
    <message>
        <source>REF ACTL.</source>
        <translation>REFIST</translation>
    </message>
    <message>
        <source>REF NOML.</source>
        <translation>REFSOLL</translation>
    </message>
    <message>
        <source>LAG</source>
        <translation>SCHPF</translation>
    </message>
    <message>
        <source>DIST.</source>
        <translation>RESTW</translation>
    </message>
    <message>
        <source>Program: %1   Machine: %2</source>
        <translation>Programm: %1   Maschine: %2</translation>
    </message>
    <message>
        <source>T %1</source>
        <translation>T %1</translation>
    </message>
    <message>
        <source>F %1 (actual %2) %3</source>
        <translation>F %1 (Ist %2) %3</translation>
    </message>
    <message>
        <source>inch/min</source>
        <translation>inch/min</translation>
    </message>
    <message>
        <source>mm/min</source>
        <translation>mm/min</translation>
    </message>
    <message>
        <source>S %1 (actual %2) rpm</source>
        <translation>S %1 (Ist %2) 1/min</translation>
    </message>
    <message>
        <source>Not referenced: Home all in Manual operation</source>
        <translation>Nicht referenziert: Alle referenzieren in Manueller Betrieb</translation>
    </message>
    <message>
        <source>Coolant on</source>
        <translation>Kühlmittel ein</translation>
    </message>
    <message>
        <source>Coolant off</source>
        <translation>Kühlmittel aus</translation>
    </message>
    <message>
        <source>inch/rev</source>
        <translation>inch/U</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/U</translation>
    </message>
    <message>
        <source>S %1 ft/min (actual %2 rpm)</source>
        <translation>S %1 ft/min (Ist %2 1/min)</translation>
    </message>
    <message>
        <source>S %1 m/min (actual %2 rpm)</source>
        <translation>S %1 m/min (Ist %2 1/min)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::ProgramFileDialog</name>
    <message>
        <source>Select file</source>
        <translation>Datei wählen</translation>
    </message>
    <message>
        <source>NC root: %1</source>
        <translation>NC-Verzeichnis: %1</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Choose a program (.H or .I)</source>
        <translation>Wählen Sie ein Programm (.H oder .I)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::ProgramPanel</name>
    <message>
        <source>Loading %1 ...</source>
        <translation>%1 wird geladen ...</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Autosave fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>Kein Programm</translation>
    </message>
    <message>
        <source>Checking the program: it runs without moving the machine</source>
        <translation>Programm wird geprüft: es läuft, ohne dass sich die Maschine bewegt</translation>
    </message>
    <message>
        <source>Program check: no errors, the program runs to its end</source>
        <translation>Programmprüfung: keine Fehler, das Programm läuft bis zum Ende</translation>
    </message>
    <message>
        <source>Program check: the program cannot run (errors: %1)</source>
        <translation>Programmprüfung: das Programm kann nicht laufen (Fehler: %1)</translation>
    </message>
    <message>
        <source>%1 was not opened: %2 could not be saved</source>
        <translation>%1 wurde nicht geöffnet: %2 konnte nicht gespeichert werden</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SettingsModel</name>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation>Achse %1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Allowed</source>
        <translation>Erlaubt</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SettingsPage</name>
    <message>
        <source>Not saved: correct the parameters first</source>
        <translation>Nicht gespeichert: zuerst die Parameter korrigieren</translation>
    </message>
    <message>
        <source>Saved %1: the changes apply when Kerf is restarted</source>
        <translation>%1 gespeichert: die Änderungen gelten nach einem Neustart von Kerf</translation>
    </message>
    <message>
        <source>Machine parameters</source>
        <translation>Maschinenparameter</translation>
    </message>
    <message>
        <source>Kerf reads the machine parameters when it starts: saved changes apply after a restart. This is a built-in machine: the parameters are saved to %1; start Kerf with --machine %1 to use them.</source>
        <translation>Kerf liest die Maschinenparameter beim Start: gespeicherte Änderungen gelten nach einem Neustart. Dies ist eine eingebaute Maschine: die Parameter werden in %1 gespeichert; Kerf mit --machine %1 starten, um sie zu verwenden.</translation>
    </message>
    <message>
        <source>Kerf reads the machine parameters when it starts: saved changes to %1 apply after a restart.</source>
        <translation>Kerf liest die Maschinenparameter beim Start: in %1 gespeicherte Änderungen gelten nach einem Neustart.</translation>
    </message>
    <message>
        <source>Wrong code number: the machine parameters stay locked</source>
        <translation>Falsche Schlüsselzahl: die Maschinenparameter bleiben gesperrt</translation>
    </message>
    <message>
        <source>Machine parameters unlocked for editing</source>
        <translation>Maschinenparameter zum Bearbeiten freigegeben</translation>
    </message>
    <message>
        <source>Code number for editing</source>
        <translation>Schlüsselzahl zum Bearbeiten</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Freigeben</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SpecialFunctionDialog</name>
    <message>
        <source>Special function</source>
        <translation>Sonderfunktion</translation>
    </message>
    <message>
        <source>Select file</source>
        <translation>Datei wählen</translation>
    </message>
</context>
<context>
    <name>kerf::ui::StatusTabs</name>
    <message>
        <source>PGM</source>
        <translation>PGM</translation>
    </message>
    <message>
        <source>TOOL</source>
        <translation>TOOL</translation>
    </message>
    <message>
        <source>TRANS</source>
        <translation>TRANS</translation>
    </message>
    <message>
        <source>PROBE</source>
        <translation>PROBE</translation>
    </message>
    <message>
        <source>%1PARA</source>
        <translation>%1PARA</translation>
    </message>
    <message>
        <source>Filter, e.g. %1</source>
        <translation>Filter, z. B. %1</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <source>Called program</source>
        <translation>Aufgerufenes Programm</translation>
    </message>
    <message>
        <source>Label</source>
        <translation>Label</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>Zyklus</translation>
    </message>
    <message>
        <source>M functions</source>
        <translation>M-Funktionen</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>inch</source>
        <translation>inch</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Korrektur</translation>
    </message>
    <message>
        <source>X (radius)</source>
        <translation>X (Radius)</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <source>Wear X (I)</source>
        <translation>Verschleiß X (I)</translation>
    </message>
    <message>
        <source>Wear Z (K)</source>
        <translation>Verschleiß Z (K)</translation>
    </message>
    <message>
        <source>Location code (F)</source>
        <translation>Lagecode (F)</translation>
    </message>
    <message>
        <source>L</source>
        <translation>L</translation>
    </message>
    <message>
        <source>DL</source>
        <translation>DL</translation>
    </message>
    <message>
        <source>DR</source>
        <translation>DR</translation>
    </message>
    <message>
        <source>Tool axis</source>
        <translation>Werkzeugachse</translation>
    </message>
    <message>
        <source>Zero offset</source>
        <translation>Nullpunktverschiebung</translation>
    </message>
    <message>
        <source>Datum shift %1</source>
        <translation>Nullpunkt-Verschiebung %1</translation>
    </message>
    <message>
        <source>Mirrored axes</source>
        <translation>Gespiegelte Achsen</translation>
    </message>
    <message>
        <source>Rotation</source>
        <translation>Drehung</translation>
    </message>
    <message>
        <source>Scaling</source>
        <translation>Maßfaktor</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>global</source>
        <translation>global</translation>
    </message>
    <message>
        <source>local, level %1</source>
        <translation>lokal, Ebene %1</translation>
    </message>
    <message>
        <source>local</source>
        <translation>lokal</translation>
    </message>
    <message>
        <source>remanent</source>
        <translation>remanent</translation>
    </message>
    <message>
        <source>text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Tastsystem</translation>
    </message>
    <message>
        <source>no result</source>
        <translation>kein Ergebnis</translation>
    </message>
    <message>
        <source>touched</source>
        <translation>berührt</translation>
    </message>
    <message>
        <source>not touched</source>
        <translation>nicht berührt</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Spindel</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Vorschub</translation>
    </message>
    <message>
        <source>S %1 %2 (constant surface speed)</source>
        <translation>S %1 %2 (konstante Schnittgeschwindigkeit)</translation>
    </message>
    <message>
        <source>ft/min</source>
        <translation>ft/min</translation>
    </message>
    <message>
        <source>m/min</source>
        <translation>m/min</translation>
    </message>
    <message>
        <source>S %1 rpm</source>
        <translation>S %1 1/min</translation>
    </message>
    <message>
        <source>limit %1 rpm</source>
        <translation>Begrenzung %1 1/min</translation>
    </message>
    <message>
        <source>in/rev</source>
        <translation>in/U</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/U</translation>
    </message>
    <message>
        <source>in/min</source>
        <translation>in/min</translation>
    </message>
    <message>
        <source>mm/min</source>
        <translation>mm/min</translation>
    </message>
    <message>
        <source>F %1 %2</source>
        <translation>F %1 %2</translation>
    </message>
    <message>
        <source>Block</source>
        <translation>Satz</translation>
    </message>
    <message>
        <source>Working plane</source>
        <translation>Bearbeitungsebene</translation>
    </message>
    <message>
        <source>Working plane %1</source>
        <translation>Bearbeitungsebene %1</translation>
    </message>
    <message>
        <source>Rotary axes</source>
        <translation>Drehachsen</translation>
    </message>
    <message>
        <source>Manual probing</source>
        <translation>Manuelles Antasten</translation>
    </message>
    <message>
        <source>Basic rotation</source>
        <translation>Grunddrehung</translation>
    </message>
    <message>
        <source>Probed %1</source>
        <translation>Angetastet %1</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>Durchmesser</translation>
    </message>
    <message>
        <source>Plane A</source>
        <translation>Ebene A</translation>
    </message>
    <message>
        <source>Plane B</source>
        <translation>Ebene B</translation>
    </message>
    <message>
        <source>Tool length T%1</source>
        <translation>Werkzeuglänge T%1</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>follows when the program is prepared</source>
        <translation>folgt, sobald das Programm vorbereitet ist</translation>
    </message>
    <message>
        <source>none</source>
        <comment>cycle</comment>
        <translation>keiner</translation>
    </message>
    <message>
        <source>none</source>
        <comment>program</comment>
        <translation>keines</translation>
    </message>
    <message>
        <source>none</source>
        <comment>called program</comment>
        <translation>keines</translation>
    </message>
    <message>
        <source>none</source>
        <comment>label</comment>
        <translation>keines</translation>
    </message>
    <message>
        <source>none</source>
        <comment>M functions</comment>
        <translation>keine</translation>
    </message>
    <message>
        <source>none</source>
        <comment>tool</comment>
        <translation>keines</translation>
    </message>
    <message>
        <source>none</source>
        <comment>mirrored axes</comment>
        <translation>keine</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TableChooser</name>
    <message>
        <source>Tool
table</source>
        <translation>Werkzeug-
tabelle</translation>
    </message>
    <message>
        <source>Preset
table</source>
        <translation>Bezugspunkt-
tabelle</translation>
    </message>
    <message>
        <source>Datum
table</source>
        <translation>Nullpunkt-
tabelle</translation>
    </message>
    <message>
        <source>Point
table</source>
        <translation>Punkte-
tabelle</translation>
    </message>
    <message>
        <source>Touch probe
table</source>
        <translation>Tastsystem-
tabelle</translation>
    </message>
    <message>
        <source>Tool
offsets</source>
        <translation>Werkzeug-
korrekturen</translation>
    </message>
    <message>
        <source>Zero
offsets</source>
        <translation>Nullpunkt-
verschiebungen</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabelle</translation>
    </message>
    <message>
        <source>Lengths, radii, wear and life of the tools</source>
        <translation>Längen, Radien, Verschleiß und Standzeit der Werkzeuge</translation>
    </message>
    <message>
        <source>Reference points of the workpieces, in machine coordinates</source>
        <translation>Bezugspunkte der Werkstücke, in Maschinenkoordinaten</translation>
    </message>
    <message>
        <source>Zero offsets relative to the active preset (CYCL DEF 7)</source>
        <translation>Nullpunkte bezogen auf den aktiven Bezugspunkt (CYCL DEF 7)</translation>
    </message>
    <message>
        <source>Machining positions for patterns (SEL PATTERN)</source>
        <translation>Bearbeitungspositionen für Muster (SEL PATTERN)</translation>
    </message>
    <message>
        <source>Workpiece touch probes: centre offset, feeds, probing path</source>
        <translation>Werkstück-Tastsysteme: Mittenversatz, Vorschübe, Antastweg</translation>
    </message>
    <message>
        <source>Tool offsets D: X, Z, nose radius R, location code F, wear I, K</source>
        <translation>Werkzeugkorrekturen D: X, Z, Schneidenradius R, Lagecode F, Verschleiß I, K</translation>
    </message>
    <message>
        <source>Zero offsets G54-G59, G159 N7-N20 and the PLC offset, from machine zero</source>
        <translation>Nullpunktverschiebungen G54-G59, G159 N7-N20 und die PLC-Verschiebung, vom Maschinen-Nullpunkt aus</translation>
    </message>
    <message>
        <source>Tools T: offset D, family, tool life, nose angle and width</source>
        <translation>Werkzeuge T: Korrektur D, Familie, Standzeit, Schneidenwinkel und -breite</translation>
    </message>
    <message>
        <source>Tables</source>
        <translation>Tabellen</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TableEditor</name>
    <message>
        <source>Search</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <source>No table</source>
        <translation>Keine Tabelle</translation>
    </message>
    <message>
        <source>Not saved: correct the table first</source>
        <translation>Nicht gespeichert: zuerst die Tabelle korrigieren</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Delete row %1 (%2)?</source>
        <translation>Zeile %1 (%2) löschen?</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabelle</translation>
    </message>
    <message>
        <source>%1 was changed on disk (e.g. by a tool measurement): reloaded</source>
        <translation>%1 wurde auf dem Datenträger geändert (z. B. durch eine Werkzeugvermessung): neu geladen</translation>
    </message>
    <message>
        <source>%1 was changed on disk while you edit it: saving would overwrite those changes</source>
        <translation>%1 wurde auf dem Datenträger geändert, während Sie sie bearbeiten: Speichern würde diese Änderungen überschreiben</translation>
    </message>
    <message>
        <source>%1 was changed on disk since it was opened here (e.g. by a tool measurement). Overwrite it with the table shown?</source>
        <translation>%1 wurde auf dem Datenträger geändert, seit sie hier geöffnet wurde (z. B. durch eine Werkzeugvermessung). Mit der angezeigten Tabelle überschreiben?</translation>
    </message>
    <message>
        <source>Not saved: the file on disk is kept</source>
        <translation>Nicht gespeichert: die Datei auf dem Datenträger bleibt</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TestRunController</name>
    <message>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <source>Test run: %1</source>
        <translation>Programm-Test: %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::UserScreenView</name>
    <message>
        <source>User screen</source>
        <translation>Anwenderbild</translation>
    </message>
    <message>
        <source>User screen - page %1</source>
        <translation>Anwenderbild - Seite %1</translation>
    </message>
    <message>
        <source>Enter IB%1 (format %2%3.%4) and press Enter</source>
        <translation>IB%1 eingeben (Format %2%3.%4) und Enter drücken</translation>
    </message>
    <message>
        <source>Waiting for a key: press a softkey</source>
        <translation>Warten auf eine Taste: einen Softkey drücken</translation>
    </message>
    <message>
        <source>The customisation program has ended</source>
        <translation>Das Anpassungsprogramm ist beendet</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Läuft</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <source>Block being edited: %1</source>
        <translation>Satz in Bearbeitung: %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::ViewportWidget</name>
    <message>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Draufsicht</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Vorderansicht</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Seitenansicht</translation>
    </message>
    <message>
        <source>Section</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
</context>
<context>
    <name>kerf::ui::WordFieldsDialog</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>kerf::ui::Workspace</name>
    <message>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <source>Program +
graphics</source>
        <translation>Programm +
Grafik</translation>
    </message>
    <message>
        <source>Program +
status</source>
        <translation>Programm +
Status</translation>
    </message>
    <message>
        <source>Positions +
status</source>
        <translation>Positionen +
Status</translation>
    </message>
</context>
<context>
    <name>kerf</name>
    <message>
        <source>Note</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Manual operation</source>
        <translation>Manueller Betrieb</translation>
    </message>
    <message>
        <source>Electronic handwheel</source>
        <translation>Elektronisches Handrad</translation>
    </message>
    <message>
        <source>Positioning with manual data input</source>
        <translation>Positionieren mit Handeingabe</translation>
    </message>
    <message>
        <source>Program run, single block</source>
        <translation>Programmlauf Einzelsatz</translation>
    </message>
    <message>
        <source>Program run, full sequence</source>
        <translation>Programmlauf Satzfolge</translation>
    </message>
    <message>
        <source>Programming</source>
        <translation>Programmieren</translation>
    </message>
    <message>
        <source>Test run</source>
        <translation>Programm-Test</translation>
    </message>
    <message>
        <source>stop the program before changing the operating mode</source>
        <translation>das Programm anhalten, bevor die Betriebsart gewechselt wird</translation>
    </message>
    <message>
        <source>programming station: no machine is connected, only Programming and Test run are available</source>
        <translation>Programmierplatz: keine Maschine angeschlossen, nur Programmieren und Programm-Test sind verfügbar</translation>
    </message>
    <message>
        <source>cannot {1}: {2}</source>
        <translation>{1} nicht möglich: {2}</translation>
    </message>
    <message>
        <source>Set-up clearance: tool tip to workpiece surface</source>
        <translation>Sicherheits-Abstand: Werkzeugspitze bis Werkstück-Oberfläche</translation>
    </message>
    <message>
        <source>Depth: workpiece surface to bottom (sign = direction)</source>
        <translation>Tiefe: Werkstück-Oberfläche bis Grund (Vorzeichen = Richtung)</translation>
    </message>
    <message>
        <source>Thread depth: workpiece surface to thread end</source>
        <translation>Gewindetiefe: Werkstück-Oberfläche bis Gewindeende</translation>
    </message>
    <message>
        <source>Plunging depth per infeed</source>
        <translation>Zustell-Tiefe je Zustellung</translation>
    </message>
    <message>
        <source>Workpiece surface coordinate</source>
        <translation>Koordinate Werkstück-Oberfläche</translation>
    </message>
    <message>
        <source>2nd set-up clearance: no collision above this height</source>
        <translation>2. Sicherheits-Abstand: keine Kollision oberhalb dieser Höhe</translation>
    </message>
    <message>
        <source>Minimum plunging depth when decreasing</source>
        <translation>Minimale Zustell-Tiefe beim Verringern</translation>
    </message>
    <message>
        <source>Feed rate for plunging</source>
        <translation>Vorschub Tiefenzustellung</translation>
    </message>
    <message>
        <source>Feed rate for milling</source>
        <translation>Vorschub Fräsen</translation>
    </message>
    <message>
        <source>Retraction feed rate (0: plunging feed)</source>
        <translation>Vorschub Rückzug (0: Vorschub Tiefenzustellung)</translation>
    </message>
    <message>
        <source>Dwell time at the top</source>
        <translation>Verweilzeit oben</translation>
    </message>
    <message>
        <source>Dwell time at depth</source>
        <translation>Verweilzeit unten</translation>
    </message>
    <message>
        <source>Decrement of the plunging depth after each infeed</source>
        <translation>Abnahmebetrag der Zustell-Tiefe nach jeder Zustellung</translation>
    </message>
    <message>
        <source>Feed rate for pre-positioning</source>
        <translation>Vorschub Vorpositionieren</translation>
    </message>
    <message>
        <source>Feed rate for countersinking</source>
        <translation>Vorschub Senken</translation>
    </message>
    <message>
        <source>Retraction distance for chip breaking</source>
        <translation>Rückzug bei Spanbruch</translation>
    </message>
    <message>
        <source>Depth for chip breaking (0: none)</source>
        <translation>Tiefe für Spanbruch (0: keiner)</translation>
    </message>
    <message>
        <source>Upper advanced stop distance</source>
        <translation>Oberer Vorhalteabstand</translation>
    </message>
    <message>
        <source>Angle for spindle orientation</source>
        <translation>Winkel für Spindel-Orientierung</translation>
    </message>
    <message>
        <source>Disengaging direction (0 none, 1 -main, 2 -secondary, 3 +main, 4 +secondary axis)</source>
        <translation>Freifahr-Richtung (0 keine, 1 -Hauptachse, 2 -Nebenachse, 3 +Hauptachse, 4 +Nebenachse)</translation>
    </message>
    <message>
        <source>Nominal diameter</source>
        <translation>Soll-Durchmesser</translation>
    </message>
    <message>
        <source>Thread pitch (+ right-hand, - left-hand)</source>
        <translation>Gewindesteigung (+ Rechtsgewinde, - Linksgewinde)</translation>
    </message>
    <message>
        <source>Climb (+1) or up-cut (-1) milling with M3</source>
        <translation>Gleichlauf- (+1) oder Gegenlauffräsen (-1) mit M3</translation>
    </message>
    <message>
        <source>Threads per step (0 one 360° helix, 1 continuous)</source>
        <translation>Gänge pro Schritt (0 eine 360°-Helix, 1 kontinuierlich)</translation>
    </message>
    <message>
        <source>Countersinking depth: surface to tool tip</source>
        <translation>Senktiefe: Oberfläche bis Werkzeugspitze</translation>
    </message>
    <message>
        <source>Total hole depth</source>
        <translation>Gesamt-Bohrtiefe</translation>
    </message>
    <message>
        <source>Clearance to side: tool edge to hole wall</source>
        <translation>Sicherheits-Abstand seitlich: Werkzeugschneide bis Bohrungswand</translation>
    </message>
    <message>
        <source>Depth at front: surface to tool tip</source>
        <translation>Tiefe stirnseitig: Oberfläche bis Werkzeugspitze</translation>
    </message>
    <message>
        <source>Countersinking offset at front (tool centre)</source>
        <translation>Versatz Senken stirnseitig (Werkzeugmitte)</translation>
    </message>
    <message>
        <source>Feed rate for approaching (0: milling feed)</source>
        <translation>Vorschub Anfahren (0: Vorschub Fräsen)</translation>
    </message>
    <message>
        <source>Deepened starting point below the surface</source>
        <translation>Vertiefter Startpunkt unter der Oberfläche</translation>
    </message>
    <message>
        <source>Depth reference (0 tool tip, 1 cylindrical part)</source>
        <translation>Tiefenbezug (0 Werkzeugspitze, 1 zylindrischer Teil)</translation>
    </message>
    <message>
        <source>cycle {1}: {2} ({3}) = {4} must be a whole number from {5} to {6}</source>
        <translation>Zyklus {1}: {2} ({3}) = {4} muss eine ganze Zahl von {5} bis {6} sein</translation>
    </message>
    <message>
        <source>cycle {1}: {2} ({3}) = {4} is outside {5} to {6}</source>
        <translation>Zyklus {1}: {2} ({3}) = {4} liegt außerhalb {5} bis {6}</translation>
    </message>
    <message>
        <source>DRILLING</source>
        <translation>BOHREN</translation>
    </message>
    <message>
        <source>REAMING</source>
        <translation>REIBEN</translation>
    </message>
    <message>
        <source>BORING</source>
        <translation>AUSDREHEN</translation>
    </message>
    <message>
        <source>Number of chip breaks before retracting</source>
        <translation>Anzahl Spanbrüche bis zum Rückzug</translation>
    </message>
    <message>
        <source>UNIVERSAL DRILLING</source>
        <translation>UNIVERSAL-BOHREN</translation>
    </message>
    <message>
        <source>Depth of counterbore from the underside (+ upwards)</source>
        <translation>Tiefe Senkung von der Unterseite (+ nach oben)</translation>
    </message>
    <message>
        <source>Material thickness</source>
        <translation>Materialstärke</translation>
    </message>
    <message>
        <source>Off-centre distance of the boring bar</source>
        <translation>Exzentermaß der Bohrstange</translation>
    </message>
    <message>
        <source>Tool edge height above the underside of the bar</source>
        <translation>Schneidenhöhe über der Unterkante der Bohrstange</translation>
    </message>
    <message>
        <source>Feed rate for counterboring</source>
        <translation>Vorschub Senken</translation>
    </message>
    <message>
        <source>Dwell time at the counterbore floor</source>
        <translation>Verweilzeit am Senkungsgrund</translation>
    </message>
    <message>
        <source>Disengaging direction (1 -main, 2 -secondary, 3 +main, 4 +secondary axis)</source>
        <translation>Freifahr-Richtung (1 -Hauptachse, 2 -Nebenachse, 3 +Hauptachse, 4 +Nebenachse)</translation>
    </message>
    <message>
        <source>BACK BORING</source>
        <translation>RÜCKWÄRTS-SENKEN</translation>
    </message>
    <message>
        <source>Lower advanced stop distance</source>
        <translation>Unterer Vorhalteabstand</translation>
    </message>
    <message>
        <source>cycle {1}: the starting point Q379 lies at or below the depth</source>
        <translation>Zyklus {1}: der Startpunkt Q379 liegt auf oder unter der Tiefe</translation>
    </message>
    <message>
        <source>UNIVERSAL PECKING</source>
        <translation>UNIVERSAL-TIEFBOHREN</translation>
    </message>
    <message>
        <source>Feed rate for helical drilling</source>
        <translation>Vorschub Helixbohren</translation>
    </message>
    <message>
        <source>Infeed per helix revolution</source>
        <translation>Zustellung pro Helix-Umdrehung</translation>
    </message>
    <message>
        <source>Roughing (pre-drilled) diameter</source>
        <translation>Vorbohr-Durchmesser</translation>
    </message>
    <message>
        <source>cycle {1}: the nominal diameter {2} is smaller than the tool diameter {3}</source>
        <translation>Zyklus {1}: der Soll-Durchmesser {2} ist kleiner als der Werkzeug-Durchmesser {3}</translation>
    </message>
    <message>
        <source>cycle {1}: the nominal diameter is more than twice the tool diameter; enter the roughing diameter Q342</source>
        <translation>Zyklus {1}: der Soll-Durchmesser ist mehr als doppelt so groß wie der Werkzeug-Durchmesser; Vorbohr-Durchmesser Q342 eingeben</translation>
    </message>
    <message>
        <source>cycle {1}: the infeed per helix Q334 must be greater than 0</source>
        <translation>Zyklus {1}: die Zustellung pro Helix Q334 muss größer als 0 sein</translation>
    </message>
    <message>
        <source>BORE MILLING</source>
        <translation>BOHRFRÄSEN</translation>
    </message>
    <message>
        <source>Select depth (0) or diameter (1)</source>
        <translation>Auswahl Tiefe (0) oder Durchmesser (1)</translation>
    </message>
    <message>
        <source>Countersink diameter (sign = direction)</source>
        <translation>Senkdurchmesser (Vorzeichen = Richtung)</translation>
    </message>
    <message>
        <source>CENTERING</source>
        <translation>ZENTRIEREN</translation>
    </message>
    <message>
        <source>Direction of rotation for entry and exit (3 M3, 4 M4, 5 stationary)</source>
        <translation>Drehrichtung beim Ein- und Ausfahren (3 M3, 4 M4, 5 Stillstand)</translation>
    </message>
    <message>
        <source>Spindle speed for entry and exit</source>
        <translation>Spindeldrehzahl beim Ein- und Ausfahren</translation>
    </message>
    <message>
        <source>Spindle speed for drilling</source>
        <translation>Spindeldrehzahl beim Bohren</translation>
    </message>
    <message>
        <source>M function for coolant on (0: none)</source>
        <translation>M-Funktion Kühlmittel EIN (0: keine)</translation>
    </message>
    <message>
        <source>M function for coolant off (0: none)</source>
        <translation>M-Funktion Kühlmittel AUS (0: keine)</translation>
    </message>
    <message>
        <source>Dwell depth where the feed reduction begins (0: none)</source>
        <translation>Verweiltiefe, ab der der Vorschub reduziert wird (0: keine)</translation>
    </message>
    <message>
        <source>Feed rate factor beyond the dwell depth</source>
        <translation>Vorschubfaktor unterhalb der Verweiltiefe</translation>
    </message>
    <message>
        <source>Maximum plunging depth</source>
        <translation>Maximale Zustell-Tiefe</translation>
    </message>
    <message>
        <source>SINGLE-LIP DEEP-HOLE DRILLING</source>
        <translation>EINLIPPEN-TIEFBOHREN</translation>
    </message>
    <message>
        <source>cycle {1}: the depth Q{2} = {3} is positive (the machine parameter displayDepthErr forbids it)</source>
        <translation>Zyklus {1}: die Tiefe Q{2} = {3} ist positiv (der Maschinenparameter displayDepthErr verbietet es)</translation>
    </message>
    <message>
        <source>cycle {1}: more than {2} infeeds; increase the plunging depth</source>
        <translation>Zyklus {1}: mehr als {2} Zustellungen; Zustell-Tiefe vergrößern</translation>
    </message>
    <message>
        <source>cycle {1} needs the point angle T-ANGLE of the tool in the tool table</source>
        <translation>Zyklus {1} braucht den Spitzenwinkel T-ANGLE des Werkzeugs in der Werkzeugtabelle</translation>
    </message>
    <message>
        <source>cycle {1} needs more than {2} moves</source>
        <translation>Zyklus {1} braucht mehr als {2} Bewegungen</translation>
    </message>
    <message>
        <source>Path overlap factor</source>
        <translation>Bahn-Überlappung Faktor</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 helical, 2 reciprocating)</source>
        <translation>Eintauchstrategie (0 senkrecht, 1 helixförmig, 2 pendelnd)</translation>
    </message>
    <message>
        <source>Set-up clearance</source>
        <translation>Sicherheits-Abstand</translation>
    </message>
    <message>
        <source>Clearance height (absolute)</source>
        <translation>Sichere Höhe (absolut)</translation>
    </message>
    <message>
        <source>Direction of rotation (+1 climb, -1 up-cut)</source>
        <translation>Drehrichtung (+1 Gleichlauf, -1 Gegenlauf)</translation>
    </message>
    <message>
        <source>Set-up clearance of the probe</source>
        <translation>Sicherheits-Abstand des Tastsystems</translation>
    </message>
    <message>
        <source>Clearance height</source>
        <translation>Sichere Höhe</translation>
    </message>
    <message>
        <source>Move to clearance height between points</source>
        <translation>Zwischen Punkten auf sichere Höhe fahren</translation>
    </message>
    <message>
        <source>Height between pattern points: 2nd set-up clearance (1) or the position at the start (0)</source>
        <translation>Höhe zwischen Musterpunkten: 2. Sicherheits-Abstand (1) oder Position beim Start (0)</translation>
    </message>
    <message>
        <source>GENERAL</source>
        <translation>ALLGEMEIN</translation>
    </message>
    <message>
        <source>POCKET MILLING</source>
        <translation>TASCHENFRÄSEN</translation>
    </message>
    <message>
        <source>CONTOUR MILLING</source>
        <translation>KONTURFRÄSEN</translation>
    </message>
    <message>
        <source>PROBING</source>
        <translation>ANTASTEN</translation>
    </message>
    <message>
        <source>POSITIONING</source>
        <translation>POSITIONIEREN</translation>
    </message>
    <message>
        <source>Centre in the 1st axis</source>
        <translation>Mitte 1. Achse</translation>
    </message>
    <message>
        <source>Centre in the 2nd axis</source>
        <translation>Mitte 2. Achse</translation>
    </message>
    <message>
        <source>Pitch circle diameter</source>
        <translation>Teilkreis-Durchmesser</translation>
    </message>
    <message>
        <source>Starting angle</source>
        <translation>Startwinkel</translation>
    </message>
    <message>
        <source>Stopping angle</source>
        <translation>Endwinkel</translation>
    </message>
    <message>
        <source>Stepping angle (0: from start, stop and count)</source>
        <translation>Winkelschritt (0: aus Start, Ende und Anzahl)</translation>
    </message>
    <message>
        <source>Number of operations</source>
        <translation>Anzahl Bearbeitungen</translation>
    </message>
    <message>
        <source>Move between operations at set-up clearance (0) or at the 2nd set-up clearance (1)</source>
        <translation>Fahren zwischen Bearbeitungen auf Sicherheits-Abstand (0) oder 2. Sicherheits-Abstand (1)</translation>
    </message>
    <message>
        <source>Type of traverse: straight line (0) or arc on the pitch circle (1)</source>
        <translation>Verfahrart: Gerade (0) oder Kreisbogen auf dem Teilkreis (1)</translation>
    </message>
    <message>
        <source>cycle {1}: the stopping angle Q246 must differ from the starting angle Q245</source>
        <translation>Zyklus {1}: der Endwinkel Q246 muss sich vom Startwinkel Q245 unterscheiden</translation>
    </message>
    <message>
        <source>POLAR PATTERN</source>
        <translation>MUSTER KREIS</translation>
    </message>
    <message>
        <source>Starting point in the 1st axis</source>
        <translation>Startpunkt 1. Achse</translation>
    </message>
    <message>
        <source>Starting point in the 2nd axis</source>
        <translation>Startpunkt 2. Achse</translation>
    </message>
    <message>
        <source>Spacing in the 1st axis</source>
        <translation>Abstand 1. Achse</translation>
    </message>
    <message>
        <source>Spacing in the 2nd axis</source>
        <translation>Abstand 2. Achse</translation>
    </message>
    <message>
        <source>Number of columns</source>
        <translation>Anzahl Spalten</translation>
    </message>
    <message>
        <source>Number of lines</source>
        <translation>Anzahl Zeilen</translation>
    </message>
    <message>
        <source>Angle of rotation about the starting point</source>
        <translation>Drehlage um den Startpunkt</translation>
    </message>
    <message>
        <source>cycle {1}: more than {2} positions</source>
        <translation>Zyklus {1}: mehr als {2} Positionen</translation>
    </message>
    <message>
        <source>CARTESIAN PATTERN</source>
        <translation>MUSTER LINIEN</translation>
    </message>
    <message>
        <source>PATTERN DEF: {1} must be a whole number from 1 to 99999</source>
        <translation>PATTERN DEF: {1} muss eine ganze Zahl von 1 bis 99999 sein</translation>
    </message>
    <message>
        <source>PATTERN DEF: more than {1} positions</source>
        <translation>PATTERN DEF: mehr als {1} Positionen</translation>
    </message>
    <message>
        <source>Engraving text</source>
        <translation>Gravurtext</translation>
    </message>
    <message>
        <source>Character height (0: scaled to the text length Q574)</source>
        <translation>Zeichenhöhe (0: auf die Textlänge Q574 skaliert)</translation>
    </message>
    <message>
        <source>Spacing factor between the characters (0: as the font)</source>
        <translation>Abstandsfaktor zwischen den Zeichen (0: wie Schriftart)</translation>
    </message>
    <message>
        <source>Font (without function)</source>
        <translation>Schriftart (ohne Funktion)</translation>
    </message>
    <message>
        <source>Text on a line (0), an arc (1) or an arc, continuous (2)</source>
        <translation>Text auf einer Geraden (0), einem Bogen (1) oder einem Bogen, umlaufend (2)</translation>
    </message>
    <message>
        <source>Angle of rotation (centre angle on an arc)</source>
        <translation>Drehlage (Mittelpunktswinkel auf einem Bogen)</translation>
    </message>
    <message>
        <source>Radius of the arc the text is on</source>
        <translation>Radius des Bogens, auf dem der Text steht</translation>
    </message>
    <message>
        <source>Reference of the text position (0-6)</source>
        <translation>Bezug der Textposition (0-6)</translation>
    </message>
    <message>
        <source>Maximum text length (0: no limit)</source>
        <translation>Maximale Textlänge (0: unbegrenzt)</translation>
    </message>
    <message>
        <source>ENGRAVING</source>
        <translation>GRAVIEREN</translation>
    </message>
    <message>
        <source>Strategy (0 meander outside, 1 meander on the edge, 2 line by line)</source>
        <translation>Strategie (0 mäanderförmig außen, 1 mäanderförmig am Rand, 2 zeilenweise)</translation>
    </message>
    <message>
        <source>Starting point in the 3rd axis (surface)</source>
        <translation>Startpunkt 3. Achse (Oberfläche)</translation>
    </message>
    <message>
        <source>End point in the 3rd axis</source>
        <translation>Endpunkt 3. Achse</translation>
    </message>
    <message>
        <source>First side length (sign = direction)</source>
        <translation>Länge der 1. Seite (Vorzeichen = Richtung)</translation>
    </message>
    <message>
        <source>Second side length (sign = direction)</source>
        <translation>Länge der 2. Seite (Vorzeichen = Richtung)</translation>
    </message>
    <message>
        <source>Finishing allowance for the floor</source>
        <translation>Schlichtaufmaß Tiefe</translation>
    </message>
    <message>
        <source>Maximum path overlap factor</source>
        <translation>Maximaler Bahn-Überlappungsfaktor</translation>
    </message>
    <message>
        <source>Feed rate for finishing</source>
        <translation>Vorschub Schlichten</translation>
    </message>
    <message>
        <source>Lateral clearance to the workpiece</source>
        <translation>Seitlicher Abstand zum Werkstück</translation>
    </message>
    <message>
        <source>cycle {1}: the starting point Q227 must be above the end point Q386</source>
        <translation>Zyklus {1}: der Startpunkt Q227 muss über dem Endpunkt Q386 liegen</translation>
    </message>
    <message>
        <source>cycle {1} needs a tool radius R greater than R2</source>
        <translation>Zyklus {1} braucht einen Werkzeugradius R größer als R2</translation>
    </message>
    <message>
        <source>FACE MILLING</source>
        <translation>PLANFRÄSEN</translation>
    </message>
    <message>
        <source>cycle 225: with the character height Q513 = 0 the text length Q574 must be given</source>
        <translation>Zyklus 225: bei Zeichenhöhe Q513 = 0 muss die Textlänge Q574 angegeben werden</translation>
    </message>
    <message>
        <source>cycle 225: the text has no length that Q574 could scale</source>
        <translation>Zyklus 225: der Text hat keine Länge, die Q574 skalieren könnte</translation>
    </message>
    <message>
        <source>cycle 225: the text is {1} mm long, longer than the maximum text length Q574 = {2}</source>
        <translation>Zyklus 225: der Text ist {1} mm lang, länger als die maximale Textlänge Q574 = {2}</translation>
    </message>
    <message>
        <source>cycle 225: text on a circle needs the radius Q517</source>
        <translation>Zyklus 225: Text auf einem Kreis braucht den Radius Q517</translation>
    </message>
    <message>
        <source>cycle 225: the character &apos;{1}&apos; cannot be engraved</source>
        <translation>Zyklus 225: das Zeichen &apos;{1}&apos; kann nicht graviert werden</translation>
    </message>
    <message>
        <source>cycle 225: unknown formatting character &apos;\{1}&apos; in the text (write \\ for a backslash)</source>
        <translation>Zyklus 225: unbekanntes Formatierungszeichen &apos;\{1}&apos; im Text (\\ für einen Backslash schreiben)</translation>
    </message>
    <message>
        <source>cycle 225: &apos;%time{1}&apos; is not a date format (use %time00 to %time15)</source>
        <translation>Zyklus 225: &apos;%time{1}&apos; ist kein Datumsformat (%time00 bis %time15 verwenden)</translation>
    </message>
    <message>
        <source>cycle 225: &apos;%count&apos; needs the number of digits (1 to 9)</source>
        <translation>Zyklus 225: &apos;%count&apos; braucht die Anzahl der Stellen (1 bis 9)</translation>
    </message>
    <message>
        <source>cycle 225: unknown escape &apos;%{1}&apos; in the text (write %% for a percent sign)</source>
        <translation>Zyklus 225: unbekanntes Steuerzeichen &apos;%{1}&apos; im Text (%% für ein Prozentzeichen schreiben)</translation>
    </message>
    <message>
        <source>Dwell time</source>
        <translation>Verweilzeit</translation>
    </message>
    <message>
        <source>Program to call as a machining cycle</source>
        <translation>Als Bearbeitungszyklus aufzurufendes Programm</translation>
    </message>
    <message>
        <source>Orientation angle of the spindle</source>
        <translation>Orientierungswinkel der Spindel</translation>
    </message>
    <message>
        <source>Tolerance (0: machine default)</source>
        <translation>Toleranz (0: Maschinen-Standardwert)</translation>
    </message>
    <message>
        <source>Filter: finishing (0) or roughing (1)</source>
        <translation>Filter: Schlichten (0) oder Schruppen (1)</translation>
    </message>
    <message>
        <source>Tolerance of rotary axes (0: machine default)</source>
        <translation>Toleranz der Drehachsen (0: Maschinen-Standardwert)</translation>
    </message>
    <message>
        <source>DWELL TIME</source>
        <translation>VERWEILZEIT</translation>
    </message>
    <message>
        <source>PGM CALL</source>
        <translation>PGM CALL</translation>
    </message>
    <message>
        <source>ORIENTED SPINDLE STOP</source>
        <translation>SPINDEL-ORIENTIERUNG</translation>
    </message>
    <message>
        <source>TOLERANCE</source>
        <translation>TOLERANZ</translation>
    </message>
    <message>
        <source>Total hole depth from the current position</source>
        <translation>Gesamt-Bohrtiefe ab der aktuellen Position</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch is 0</source>
        <translation>Zyklus {1}: die Gewindesteigung ist 0</translation>
    </message>
    <message>
        <source>THREAD CUTTING</source>
        <translation>GEWINDESCHNEIDEN</translation>
    </message>
    <message>
        <source>Feed rate for tapping (spindle speed x pitch)</source>
        <translation>Vorschub Gewindebohren (Spindeldrehzahl x Steigung)</translation>
    </message>
    <message>
        <source>cycle {1} needs the spindle running (M3 or M4)</source>
        <translation>Zyklus {1} braucht eine laufende Spindel (M3 oder M4)</translation>
    </message>
    <message>
        <source>TAPPING WITH A FLOATING TAP HOLDER</source>
        <translation>GEWINDEBOHREN MIT AUSGLEICHSFUTTER</translation>
    </message>
    <message>
        <source>RIGID TAPPING</source>
        <translation>GEWINDEBOHREN OHNE AUSGLEICHSFUTTER</translation>
    </message>
    <message>
        <source>Retraction for chip breaking in pitches (0: out of the hole)</source>
        <translation>Rückzug bei Spanbruch in Gewindegängen (0: aus der Bohrung)</translation>
    </message>
    <message>
        <source>Spindle speed factor for retraction</source>
        <translation>Faktor Spindeldrehzahl beim Rückzug</translation>
    </message>
    <message>
        <source>TAPPING WITH CHIP BREAKING</source>
        <translation>GEWINDEBOHREN SPANBRUCH</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch {2} differs from the pitch {3} of the tool in the tool table</source>
        <translation>Zyklus {1}: die Gewindesteigung {2} weicht von der Steigung {3} des Werkzeugs in der Werkzeugtabelle ab</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch Q{2} is 0</source>
        <translation>Zyklus {1}: die Gewindesteigung Q{2} ist 0</translation>
    </message>
    <message>
        <source>THREAD MILLING</source>
        <translation>GEWINDEFRÄSEN</translation>
    </message>
    <message>
        <source>THREAD MILLING/COUNTERSINKING</source>
        <translation>SENKGEWINDEFRÄSEN</translation>
    </message>
    <message>
        <source>THREAD DRILLING/MILLING</source>
        <translation>BOHRGEWINDEFRÄSEN</translation>
    </message>
    <message>
        <source>Countersink before (0) or after (1) the thread</source>
        <translation>Senken vor (0) oder nach (1) dem Gewinde</translation>
    </message>
    <message>
        <source>HELICAL THREAD DRILLING/MILLING</source>
        <translation>HELIX-BOHRGEWINDEFRÄSEN</translation>
    </message>
    <message>
        <source>Countersinking offset at front: stud centre to tool centre</source>
        <translation>Versatz Senken stirnseitig: Zapfenmitte bis Werkzeugmitte</translation>
    </message>
    <message>
        <source>OUTSIDE THREAD MILLING</source>
        <translation>AUSSENGEWINDE FRÄSEN</translation>
    </message>
    <message>
        <source>cycle {1}: the tool diameter {2} is too large for the nominal diameter {3}</source>
        <translation>Zyklus {1}: der Werkzeug-Durchmesser {2} ist zu groß für den Soll-Durchmesser {3}</translation>
    </message>
    <message>
        <source>cycle {1}: unexpected &apos;{2}&apos;</source>
        <translation>Zyklus {1}: unerwartetes &apos;{2}&apos;</translation>
    </message>
    <message>
        <source>cycle {1}: {2} needs a value</source>
        <translation>Zyklus {1}: {2} braucht einen Wert</translation>
    </message>
    <message>
        <source>cycle {1}: scaling factor {2} = {3} is outside 0.000001 to 99.999999</source>
        <translation>Zyklus {1}: Maßfaktor {2} = {3} liegt außerhalb 0.000001 bis 99.999999</translation>
    </message>
    <message>
        <source>Datum shift per axis (IX: incremental), or #n: datum number of the datum table</source>
        <translation>Nullpunkt-Verschiebung je Achse (IX: inkremental) oder #n: Nullpunkt-Nummer der Nullpunkttabelle</translation>
    </message>
    <message>
        <source>Mirrored axes (none: mirroring off)</source>
        <translation>Gespiegelte Achsen (keine: Spiegelung aus)</translation>
    </message>
    <message>
        <source>Angle of rotation (IROT: incremental)</source>
        <translation>Drehwinkel (IROT: inkremental)</translation>
    </message>
    <message>
        <source>Scaling factor</source>
        <translation>Maßfaktor</translation>
    </message>
    <message>
        <source>Scaling factor per axis</source>
        <translation>Maßfaktor je Achse</translation>
    </message>
    <message>
        <source>Centre of the scaling per axis</source>
        <translation>Streckungszentrum je Achse</translation>
    </message>
    <message>
        <source>Number of the preset to activate</source>
        <translation>Nummer des zu aktivierenden Bezugspunkts</translation>
    </message>
    <message>
        <source>Tilt angles of the rotary axes</source>
        <translation>Schwenkwinkel der Drehachsen</translation>
    </message>
    <message>
        <source>Feed rate for automatic positioning</source>
        <translation>Vorschub automatisches Positionieren</translation>
    </message>
    <message>
        <source>Set-up clearance for automatic positioning</source>
        <translation>Sicherheits-Abstand für das automatische Positionieren</translation>
    </message>
    <message>
        <source>cycle {1}: angle of rotation ROT = {2} is outside -360 to 360</source>
        <translation>Zyklus {1}: Drehwinkel ROT = {2} liegt außerhalb -360 bis 360</translation>
    </message>
    <message>
        <source>DATUM SHIFT</source>
        <translation>NULLPUNKT-VERSCHIEBUNG</translation>
    </message>
    <message>
        <source>MIRROR IMAGE</source>
        <translation>SPIEGELUNG</translation>
    </message>
    <message>
        <source>ROTATION</source>
        <translation>DREHUNG</translation>
    </message>
    <message>
        <source>SCALING</source>
        <translation>MASSFAKTOR</translation>
    </message>
    <message>
        <source>AXIS-SPECIFIC SCALING</source>
        <translation>MASSFAKTOR ACHSSPEZIFISCH</translation>
    </message>
    <message>
        <source>PRESETTING</source>
        <translation>BEZUGSPUNKT SETZEN</translation>
    </message>
    <message>
        <source>WORKING PLANE</source>
        <translation>BEARBEITUNGSEBENE</translation>
    </message>
    <message>
        <source>the block is longer than 60000 characters</source>
        <translation>der Satz ist länger als 60000 Zeichen</translation>
    </message>
    <message>
        <source>empty block: a block needs at least a comment</source>
        <translation>leerer Satz: ein Satz braucht mindestens einen Kommentar</translation>
    </message>
    <message>
        <source>a block has at most 3 skip marks</source>
        <translation>ein Satz hat höchstens 3 Ausblendzeichen</translation>
    </message>
    <message>
        <source>a block label cannot be a parameter</source>
        <translation>eine Satzmarke kann kein Parameter sein</translation>
    </message>
    <message>
        <source>label number expected after N</source>
        <translation>Marken-Nummer nach N erwartet</translation>
    </message>
    <message>
        <source>a label has at most 8 digits (N0-N99999999)</source>
        <translation>eine Marke hat höchstens 8 Stellen (N0-N99999999)</translation>
    </message>
    <message>
        <source>missing &apos;)&apos; at the end of the high-level block</source>
        <translation>&apos;)&apos; am Ende des Hochsprachen-Satzes fehlt</translation>
    </message>
    <message>
        <source>repetition count expected after N</source>
        <translation>Wiederholungszahl nach N erwartet</translation>
    </message>
    <message>
        <source>a repetition count has at most 4 digits (N0-N9999)</source>
        <translation>eine Wiederholungszahl hat höchstens 4 Stellen (N0-N9999)</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; at the end of the block</source>
        <translation>unerwartetes &apos;{1}&apos; am Satzende</translation>
    </message>
    <message>
        <source>expressions are not allowed in ISO blocks</source>
        <translation>Ausdrücke sind in ISO-Sätzen nicht erlaubt</translation>
    </message>
    <message>
        <source>parameter number expected after P</source>
        <translation>Parameter-Nummer nach P erwartet</translation>
    </message>
    <message>
        <source>number expected after the sign of {1}</source>
        <translation>Zahl nach dem Vorzeichen von {1} erwartet</translation>
    </message>
    <message>
        <source>{1} cannot be negative</source>
        <translation>{1} darf nicht negativ sein</translation>
    </message>
    <message>
        <source>{1} value {2} is outside the format {3}.{4}</source>
        <translation>{1}-Wert {2} liegt außerhalb des Formats {3}.{4}</translation>
    </message>
    <message>
        <source>{1} is outside the format {2}.{3}</source>
        <translation>{1} liegt außerhalb des Formats {2}.{3}</translation>
    </message>
    <message>
        <source>{1} must be a whole number from {2} to {3}</source>
        <translation>{1} muss eine ganze Zahl von {2} bis {3} sein</translation>
    </message>
    <message>
        <source>{1} is programmed twice</source>
        <translation>{1} ist doppelt programmiert</translation>
    </message>
    <message>
        <source>&apos;{1}&apos;: words are written in upper case</source>
        <translation>&apos;{1}&apos;: Wörter werden in Großbuchstaben geschrieben</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos;</source>
        <translation>unerwartetes &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>G functions are written at the start of the block</source>
        <translation>G-Funktionen stehen am Satzanfang</translation>
    </message>
    <message>
        <source>too many G functions in one block</source>
        <translation>zu viele G-Funktionen in einem Satz</translation>
    </message>
    <message>
        <source>axis letters after G14, G16 or G74 take no value</source>
        <translation>Achsbuchstaben nach G14, G16 oder G74 haben keinen Wert</translation>
    </message>
    <message>
        <source>I is programmed more than twice</source>
        <translation>I ist mehr als zweimal programmiert</translation>
    </message>
    <message>
        <source>at most 7 M functions in one block</source>
        <translation>höchstens 7 M-Funktionen in einem Satz</translation>
    </message>
    <message>
        <source>E belongs to G51</source>
        <translation>E gehört zu G51</translation>
    </message>
    <message>
        <source>unknown word &apos;{1}&apos;</source>
        <translation>unbekanntes Wort &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 cannot be used in a thread</source>
        <translation>G36, G37, G38 und G39 sind in einem Gewinde nicht erlaubt</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 need a move in the plane</source>
        <translation>G36, G37, G38 und G39 brauchen eine Bewegung in der Ebene</translation>
    </message>
    <message>
        <source>the next block must be a contour element in the plane</source>
        <translation>der nächste Satz muss ein Konturelement in der Ebene sein</translation>
    </message>
    <message>
        <source>G37 needs a straight line (G00 or G01)</source>
        <translation>G37 braucht eine Gerade (G00 oder G01)</translation>
    </message>
    <message>
        <source>G37: the start point lies inside the entry circle</source>
        <translation>G37: der Startpunkt liegt im Anfahrkreis</translation>
    </message>
    <message>
        <source>G36: the rounding radius does not fit between the elements</source>
        <translation>G36: der Rundungsradius passt nicht zwischen die Elemente</translation>
    </message>
    <message>
        <source>G39 needs straight lines on both sides</source>
        <translation>G39 braucht auf beiden Seiten Geraden</translation>
    </message>
    <message>
        <source>G39: the chamfer is longer than an adjacent line</source>
        <translation>G39: die Fase ist länger als eine angrenzende Gerade</translation>
    </message>
    <message>
        <source>the block after G38 must be a straight line (G00 or G01)</source>
        <translation>der Satz nach G38 muss eine Gerade sein (G00 oder G01)</translation>
    </message>
    <message>
        <source>G38: the end point lies inside the exit circle</source>
        <translation>G38: der Endpunkt liegt im Abfahrkreis</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 need a following contour element</source>
        <translation>G36, G37, G38 und G39 brauchen ein folgendes Konturelement</translation>
    </message>
    <message>
        <source>division by zero</source>
        <translation>Division durch Null</translation>
    </message>
    <message>
        <source>EXP: {1} to the power {2} has no value</source>
        <translation>EXP: {1} hoch {2} hat keinen Wert</translation>
    </message>
    <message>
        <source>MOD by zero</source>
        <translation>MOD durch Null</translation>
    </message>
    <message>
        <source>&apos;)&apos; expected</source>
        <translation>&apos;)&apos; erwartet</translation>
    </message>
    <message>
        <source>a function argument needs parentheses unless it is a number</source>
        <translation>ein Funktionsargument braucht Klammern, außer es ist eine Zahl</translation>
    </message>
    <message>
        <source>{1}: {2} is outside its domain</source>
        <translation>{1}: {2} liegt außerhalb des Definitionsbereichs</translation>
    </message>
    <message>
        <source>a hexadecimal constant has 1 to 8 digits</source>
        <translation>eine Hexadezimal-Konstante hat 1 bis 8 Stellen</translation>
    </message>
    <message>
        <source>number expected</source>
        <translation>Zahl erwartet</translation>
    </message>
    <message>
        <source>a constant has at most 6 integer and 5 decimal digits</source>
        <translation>eine Konstante hat höchstens 6 Vorkomma- und 5 Nachkommastellen</translation>
    </message>
    <message>
        <source>an index must be a whole number, not {1}</source>
        <translation>ein Index muss eine ganze Zahl sein, nicht {1}</translation>
    </message>
    <message>
        <source>number or (expression) expected</source>
        <translation>Zahl oder (Ausdruck) erwartet</translation>
    </message>
    <message>
        <source>GPOS needs N&lt;block&gt;</source>
        <translation>GPOS braucht N&lt;Satz&gt;</translation>
    </message>
    <message>
        <source>GPOS needs P&lt;program&gt;</source>
        <translation>GPOS braucht P&lt;Programm&gt;</translation>
    </message>
    <message>
        <source>{1} needs a number</source>
        <translation>{1} braucht eine Zahl</translation>
    </message>
    <message>
        <source>value expected</source>
        <translation>Wert erwartet</translation>
    </message>
    <message>
        <source>&apos;(&apos; expected</source>
        <translation>&apos;(&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;,&apos; expected</source>
        <translation>&apos;,&apos; erwartet</translation>
    </message>
    <message>
        <source>label N{1} is not defined in this program</source>
        <translation>Marke N{1} ist in diesem Programm nicht definiert</translation>
    </message>
    <message>
        <source>label N{1} is not defined in the program</source>
        <translation>Marke N{1} ist im Programm nicht definiert</translation>
    </message>
    <message>
        <source>RPT: block N{1} comes before block N{2}</source>
        <translation>RPT: Satz N{1} steht vor Satz N{2}</translation>
    </message>
    <message>
        <source>more than {1} nested levels</source>
        <translation>mehr als {1} Verschachtelungsebenen</translation>
    </message>
    <message>
        <source>cannot read program {1}: {2}</source>
        <translation>Programm {1} kann nicht gelesen werden: {2}</translation>
    </message>
    <message>
        <source>program {1} has errors</source>
        <translation>Programm {1} enthält Fehler</translation>
    </message>
    <message>
        <source>program {1} is not in the NC root</source>
        <translation>Programm {1} liegt nicht im NC-Verzeichnis</translation>
    </message>
    <message>
        <source>subroutine {1} is not defined</source>
        <translation>Unterprogramm {1} ist nicht definiert</translation>
    </message>
    <message>
        <source>subroutine {1} is defined in more than one program</source>
        <translation>Unterprogramm {1} ist in mehr als einem Programm definiert</translation>
    </message>
    <message>
        <source>the program with subroutine {1} has errors</source>
        <translation>das Programm mit Unterprogramm {1} enthält Fehler</translation>
    </message>
    <message>
        <source>error 1255: subroutine restricted to OEM programs</source>
        <translation>Fehler 1255: Unterprogramm nur für OEM-Programme</translation>
    </message>
    <message>
        <source>more than 6 nested levels of local parameters</source>
        <translation>mehr als 6 Verschachtelungsebenen lokaler Parameter</translation>
    </message>
    <message>
        <source>subroutine {1} has no RET</source>
        <translation>Unterprogramm {1} hat kein RET</translation>
    </message>
    <message>
        <source>RET outside a subroutine</source>
        <translation>RET außerhalb eines Unterprogramms</translation>
    </message>
    <message>
        <source>error 1064: program cannot be executed (MEXEC inside the modal program)</source>
        <translation>Fehler 1064: Programm kann nicht ausgeführt werden (MEXEC im modalen Programm)</translation>
    </message>
    <message>
        <source>REPOS is only allowed in an interrupt subroutine</source>
        <translation>REPOS ist nur in einem Interrupt-Unterprogramm erlaubt</translation>
    </message>
    <message>
        <source>REPOS failed</source>
        <translation>REPOS fehlgeschlagen</translation>
    </message>
    <message>
        <source>collision detection removed a loop of the compensated path</source>
        <translation>die Kollisionsüberwachung hat eine Schleife aus der korrigierten Bahn entfernt</translation>
    </message>
    <message>
        <source>the program ends before the last block of the RPT</source>
        <translation>das Programm endet vor dem letzten Satz des RPT</translation>
    </message>
    <message>
        <source>the program ends inside a subroutine (RET missing)</source>
        <translation>das Programm endet in einem Unterprogramm (RET fehlt)</translation>
    </message>
    <message>
        <source>axis {1} is not available on this machine</source>
        <translation>Achse {1} ist an dieser Maschine nicht vorhanden</translation>
    </message>
    <message>
        <source>N{1}: only a motion block under a modal subroutine (MCALL, MEXEC) or a canned cycle can be repeated</source>
        <translation>N{1}: nur ein Verfahrsatz unter einem modalen Unterprogramm (MCALL, MEXEC) oder einem Festzyklus kann wiederholt werden</translation>
    </message>
    <message>
        <source>incompatible G functions G51 and {1} (error 7)</source>
        <translation>unverträgliche G-Funktionen G51 und {1} (Fehler 7)</translation>
    </message>
    <message>
        <source>G40, G41 and G42 need G00 or G01 active, not G02/G03</source>
        <translation>G40, G41 und G42 brauchen aktives G00 oder G01, nicht G02/G03</translation>
    </message>
    <message>
        <source>radius compensation works in the ZX plane only (PLACOMP 0)</source>
        <translation>die Radiuskorrektur wirkt nur in der ZX-Ebene (PLACOMP 0)</translation>
    </message>
    <message>
        <source>{1} needs R greater than 0 right after it</source>
        <translation>{1} braucht unmittelbar danach R größer als 0</translation>
    </message>
    <message>
        <source>G37 needs R greater than 0 right after it</source>
        <translation>G37 braucht unmittelbar danach R größer als 0</translation>
    </message>
    <message>
        <source>G37 needs a straight line (G00 or G01), not G02/G03</source>
        <translation>G37 braucht eine Gerade (G00 oder G01), nicht G02/G03</translation>
    </message>
    <message>
        <source>G06 belongs in a circular interpolation block</source>
        <translation>G06 gehört in einen Satz mit Kreisinterpolation</translation>
    </message>
    <message>
        <source>G16 needs two axis letters: abscissa and ordinate</source>
        <translation>G16 braucht zwei Achsbuchstaben: Abszisse und Ordinate</translation>
    </message>
    <message>
        <source>G16 {1}{2}: only planes of two of the axes X, Y and Z are supported</source>
        <translation>G16 {1}{2}: nur Ebenen aus zwei der Achsen X, Y und Z werden unterstützt</translation>
    </message>
    <message>
        <source>the plane cannot change under radius compensation</source>
        <translation>die Ebene kann bei aktiver Radiuskorrektur nicht wechseln</translation>
    </message>
    <message>
        <source>G51 needs E, the permitted contour error</source>
        <translation>G51 braucht E, den zulässigen Konturfehler</translation>
    </message>
    <message>
        <source>G72 S: the scale factor must be greater than 0</source>
        <translation>G72 S: der Maßfaktor muss größer als 0 sein</translation>
    </message>
    <message>
        <source>G72 needs S or axis factors</source>
        <translation>G72 braucht S oder Achsfaktoren</translation>
    </message>
    <message>
        <source>G72: the scale factor of {1} must be greater than 0</source>
        <translation>G72: der Maßfaktor von {1} muss größer als 0 sein</translation>
    </message>
    <message>
        <source>{1} needs K, the zone number 1-4</source>
        <translation>{1} braucht K, die Bereichsnummer 1-4</translation>
    </message>
    <message>
        <source>G22 needs S0 (off), S1 (no entry) or S2 (no exit)</source>
        <translation>G22 braucht S0 (aus), S1 (kein Einfahren) oder S2 (kein Ausfahren)</translation>
    </message>
    <message>
        <source>G74 alone runs the subroutine of REFPSUB, which is not set</source>
        <translation>G74 allein führt das Unterprogramm aus REFPSUB aus, das nicht gesetzt ist</translation>
    </message>
    <message>
        <source>G159 needs N1-N20</source>
        <translation>G159 braucht N1-N20</translation>
    </message>
    <message>
        <source>G96 needs S: no cutting speed was programmed before</source>
        <translation>G96 braucht S: zuvor wurde keine Schnittgeschwindigkeit programmiert</translation>
    </message>
    <message>
        <source>G96 needs a spindle gear range (M41-M44) first</source>
        <translation>G96 braucht zuerst eine Spindel-Getriebestufe (M41-M44)</translation>
    </message>
    <message>
        <source>S{1} is above the spindle limit of {2} rpm</source>
        <translation>S{1} liegt über der Spindelgrenze von {2} 1/min</translation>
    </message>
    <message>
        <source>M{1} has a subroutine: it must be alone in its block</source>
        <translation>M{1} hat ein Unterprogramm: es muss allein im Satz stehen</translation>
    </message>
    <message>
        <source>polar coordinates (R, Q) and Cartesian coordinates of the plane in one block</source>
        <translation>Polarkoordinaten (R, Q) und kartesische Koordinaten der Ebene in einem Satz</translation>
    </message>
    <message>
        <source>the polar radius becomes negative</source>
        <translation>der Polarradius wird negativ</translation>
    </message>
    <message>
        <source>an angle Q with both coordinates of the plane</source>
        <translation>ein Winkel Q mit beiden Koordinaten der Ebene</translation>
    </message>
    <message>
        <source>angle Q {1}: the path cannot reach that abscissa</source>
        <translation>Winkel Q {1}: die Bahn kann diese Abszisse nicht erreichen</translation>
    </message>
    <message>
        <source>angle Q {1}: the path cannot reach that ordinate</source>
        <translation>Winkel Q {1}: die Bahn kann diese Ordinate nicht erreichen</translation>
    </message>
    <message>
        <source>J is the centre of the Y axis: the ZX plane uses I and K</source>
        <translation>J ist der Mittelpunkt der Y-Achse: die ZX-Ebene verwendet I und K</translation>
    </message>
    <message>
        <source>G08 needs a previous path in the plane to be tangent to</source>
        <translation>G08 braucht eine vorherige Bahn in der Ebene, an die tangential angeschlossen wird</translation>
    </message>
    <message>
        <source>G08 cannot program a full circle</source>
        <translation>G08 kann keinen Vollkreis programmieren</translation>
    </message>
    <message>
        <source>G08: the end point lies on the tangent of the previous path</source>
        <translation>G08: der Endpunkt liegt auf der Tangente der vorherigen Bahn</translation>
    </message>
    <message>
        <source>G09 cannot program a full circle</source>
        <translation>G09 kann keinen Vollkreis programmieren</translation>
    </message>
    <message>
        <source>G09: the three points lie on a line</source>
        <translation>G09: die drei Punkte liegen auf einer Geraden</translation>
    </message>
    <message>
        <source>a full circle cannot be programmed with R</source>
        <translation>ein Vollkreis kann nicht mit R programmiert werden</translation>
    </message>
    <message>
        <source>the arc radius R is too small for the end point</source>
        <translation>der Kreisradius R ist zu klein für den Endpunkt</translation>
    </message>
    <message>
        <source>the start and end radii differ by {1} mm (more than CIRINERR)</source>
        <translation>Start- und Endradius unterscheiden sich um {1} mm (mehr als CIRINERR)</translation>
    </message>
    <message>
        <source>the arc has no radius</source>
        <translation>der Kreisbogen hat keinen Radius</translation>
    </message>
    <message>
        <source>arc centre or radius beyond 214748.3647 mm</source>
        <translation>Kreismittelpunkt oder Radius über 214748.3647 mm</translation>
    </message>
    <message>
        <source>Q (spindle angle) needs M19TYPE = 1</source>
        <translation>Q (Spindelwinkel) braucht M19TYPE = 1</translation>
    </message>
    <message>
        <source>only the first thread of a joined chain may have Q</source>
        <translation>nur das erste Gewinde einer verketteten Folge darf Q haben</translation>
    </message>
    <message>
        <source>Q must be within +-359.9999 degrees</source>
        <translation>Q muss innerhalb +-359.9999 Grad liegen</translation>
    </message>
    <message>
        <source>a thread needs its pitch L</source>
        <translation>ein Gewinde braucht seine Steigung L</translation>
    </message>
    <message>
        <source>two variable-pitch threads cannot be joined; end one with G34 L0 K0</source>
        <translation>zwei Gewinde mit variabler Steigung können nicht verkettet werden; eines mit G34 L0 K0 beenden</translation>
    </message>
    <message>
        <source>G34 joined to G33 must start with the pitch of the G33</source>
        <translation>G34 verkettet mit G33 muss mit der Steigung des G33 beginnen</translation>
    </message>
    <message>
        <source>after G34 a constant pitch is programmed with G34 L0 K0</source>
        <translation>nach G34 wird eine konstante Steigung mit G34 L0 K0 programmiert</translation>
    </message>
    <message>
        <source>the thread pitch must be greater than 0</source>
        <translation>die Gewindesteigung muss größer als 0 sein</translation>
    </message>
    <message>
        <source>the variable pitch reaches zero before the end point</source>
        <translation>die variable Steigung erreicht vor dem Endpunkt Null</translation>
    </message>
    <message>
        <source>G53 works with G00 and G01 moves only</source>
        <translation>G53 wirkt nur mit G00- und G01-Bewegungen</translation>
    </message>
    <message>
        <source>G52 moves one axis</source>
        <translation>G52 bewegt eine Achse</translation>
    </message>
    <message>
        <source>no tool offset table: offset D{1} and the following ones are all zero</source>
        <translation>keine Werkzeugkorrekturtabelle: Korrektur D{1} und alle folgenden sind Null</translation>
    </message>
    <message>
        <source>the header should be %comment,attributes, (two commas)</source>
        <translation>der Programmkopf sollte %Kommentar,Attribute, lauten (zwei Kommas)</translation>
    </message>
    <message>
        <source>the program comment has more than 20 characters</source>
        <translation>der Programmkommentar hat mehr als 20 Zeichen</translation>
    </message>
    <message>
        <source>words out of the order G, coordinates, F, S, T, D, M</source>
        <translation>Wörter nicht in der Reihenfolge G, Koordinaten, F, S, T, D, M</translation>
    </message>
    <message>
        <source>subroutine {1} starts before subroutine {2} has its RET</source>
        <translation>Unterprogramm {1} beginnt, bevor Unterprogramm {2} sein RET hat</translation>
    </message>
    <message>
        <source>error 63: program subroutine numbers from 1 to 9999 (10000-20000 only in OEM programs)</source>
        <translation>Fehler 63: Unterprogrammnummern von 1 bis 9999 programmieren (10000-20000 nur in OEM-Programmen)</translation>
    </message>
    <message>
        <source>subroutine {1} is defined twice</source>
        <translation>Unterprogramm {1} ist doppelt definiert</translation>
    </message>
    <message>
        <source>programs on a PC over DNC are not available; the program cannot run past this block</source>
        <translation>Programme auf einem PC über DNC sind nicht verfügbar; das Programm kann nicht über diesen Satz hinaus laufen</translation>
    </message>
    <message>
        <source>label N{1} is used more than once; jumps go to the first one</source>
        <translation>Marke N{1} wird mehrfach verwendet; Sprünge gehen zur ersten</translation>
    </message>
    <message>
        <source>incompatible G functions</source>
        <translation>unverträgliche G-Funktionen</translation>
    </message>
    <message>
        <source>program subroutine number from 1 to 9999</source>
        <translation>Unterprogrammnummer von 1 bis 9999 programmieren</translation>
    </message>
    <message>
        <source>the S that changes the gear range must be alone in its block</source>
        <translation>das S, das die Getriebestufe wechselt, muss allein im Satz stehen</translation>
    </message>
    <message>
        <source>program cannot be executed</source>
        <translation>Programm kann nicht ausgeführt werden</translation>
    </message>
    <message>
        <source>subroutine restricted to OEM program</source>
        <translation>Unterprogramm nur für OEM-Programm</translation>
    </message>
    <message>
        <source>{1}</source>
        <translation>{1}</translation>
    </message>
    <message>
        <source>error {1}</source>
        <translation>Fehler {1}</translation>
    </message>
    <message>
        <source>error {1}: {2}</source>
        <translation>Fehler {1}: {2}</translation>
    </message>
    <message>
        <source>DGWZ: Z minimum &lt; Z maximum and 0 &lt;= inner &lt; outer</source>
        <translation>DGWZ: Z minimal &lt; Z maximal und 0 &lt;= innen &lt; außen</translation>
    </message>
    <message>
        <source>program {1} exists: OPEN needs A (append) or D (delete)</source>
        <translation>Programm {1} existiert: OPEN braucht A (anhängen) oder D (löschen)</translation>
    </message>
    <message>
        <source>program {1} is running: it cannot be opened</source>
        <translation>Programm {1} läuft: es kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>WRITE needs a program opened with OPEN</source>
        <translation>WRITE braucht ein mit OPEN geöffnetes Programm</translation>
    </message>
    <message>
        <source>GPOS: program {1} has no block N{2}</source>
        <translation>GPOS: Programm {1} hat keinen Satz N{2}</translation>
    </message>
    <message>
        <source>GPOS: block not found</source>
        <translation>GPOS: Satz nicht gefunden</translation>
    </message>
    <message>
        <source>{1} is not available on the simulated machine</source>
        <translation>{1} ist an der simulierten Maschine nicht verfügbar</translation>
    </message>
    <message>
        <source>{1} cannot be read from a part program (PLC or DNC only)</source>
        <translation>{1} kann nicht aus einem Teileprogramm gelesen werden (nur PLC oder DNC)</translation>
    </message>
    <message>
        <source>{1}: the simulated machine has no tool magazine</source>
        <translation>{1}: die simulierte Maschine hat kein Werkzeugmagazin</translation>
    </message>
    <message>
        <source>{1}: offsets are numbered 0-255</source>
        <translation>{1}: Korrekturen sind von 0-255 nummeriert</translation>
    </message>
    <message>
        <source>{1}: zero offsets are 54-59 and 1-20</source>
        <translation>{1}: Nullpunktverschiebungen sind 54-59 und 1-20</translation>
    </message>
    <message>
        <source>NBTOOL can only be read in the tool change subroutine</source>
        <translation>NBTOOL kann nur im Werkzeugwechsel-Unterprogramm gelesen werden</translation>
    </message>
    <message>
        <source>MS{1}: the state is kept for M00-M06, M08, M09, M19, M30 and M41-M44</source>
        <translation>MS{1}: der Zustand wird für M00-M06, M08, M09, M19, M30 und M41-M44 gespeichert</translation>
    </message>
    <message>
        <source>{1}: outputs 1-8</source>
        <translation>{1}: Ausgänge 1-8</translation>
    </message>
    <message>
        <source>{1} is read-only in a part program</source>
        <translation>{1} ist in einem Teileprogramm nur lesbar</translation>
    </message>
    <message>
        <source>PRGFRO: 0-255 %</source>
        <translation>PRGFRO: 0-255 %</translation>
    </message>
    <message>
        <source>PRGSSO: 0-255 %</source>
        <translation>PRGSSO: 0-255 %</translation>
    </message>
    <message>
        <source>{1}: offsets are D1-D255 and F is 0-9</source>
        <translation>{1}: Korrekturen sind D1-D255 und F ist 0-9</translation>
    </message>
    <message>
        <source>{1}: value out of range</source>
        <translation>{1}: Wert außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>KEY can only be written in a customisation program</source>
        <translation>KEY kann nur in einem Anpassungsprogramm geschrieben werden</translation>
    </message>
    <message>
        <source>KEYSRC can only be changed while it is 0</source>
        <translation>KEYSRC kann nur geändert werden, solange es 0 ist</translation>
    </message>
    <message>
        <source>{1}: free outputs 1-4, -10 to 10 V</source>
        <translation>{1}: freie Ausgänge 1-4, -10 bis 10 V</translation>
    </message>
    <message>
        <source>rapid positioning</source>
        <translation>Positionieren im Eilgang</translation>
    </message>
    <message>
        <source>linear interpolation</source>
        <translation>Linearinterpolation</translation>
    </message>
    <message>
        <source>circular interpolation clockwise</source>
        <translation>Kreisinterpolation im Uhrzeigersinn</translation>
    </message>
    <message>
        <source>circular interpolation counter-clockwise</source>
        <translation>Kreisinterpolation gegen den Uhrzeigersinn</translation>
    </message>
    <message>
        <source>dwell / stop block preparation</source>
        <translation>Verweilzeit / Satzvorbereitung anhalten</translation>
    </message>
    <message>
        <source>round corner</source>
        <translation>verrundete Ecke</translation>
    </message>
    <message>
        <source>arc centre in absolute coordinates</source>
        <translation>Kreismittelpunkt in absoluten Koordinaten</translation>
    </message>
    <message>
        <source>sharp corner</source>
        <translation>scharfe Ecke</translation>
    </message>
    <message>
        <source>arc tangent to the previous path</source>
        <translation>Kreisbogen tangential an die vorherige Bahn</translation>
    </message>
    <message>
        <source>arc through three points</source>
        <translation>Kreisbogen durch drei Punkte</translation>
    </message>
    <message>
        <source>mirror image off</source>
        <translation>Spiegelung aus</translation>
    </message>
    <message>
        <source>mirror image in X</source>
        <translation>Spiegelung in X</translation>
    </message>
    <message>
        <source>mirror image in Y</source>
        <translation>Spiegelung in Y</translation>
    </message>
    <message>
        <source>mirror image in Z</source>
        <translation>Spiegelung in Z</translation>
    </message>
    <message>
        <source>mirror image in the programmed axes</source>
        <translation>Spiegelung in den programmierten Achsen</translation>
    </message>
    <message>
        <source>main plane by two axes</source>
        <translation>Hauptebene durch zwei Achsen</translation>
    </message>
    <message>
        <source>main plane XY</source>
        <translation>Hauptebene XY</translation>
    </message>
    <message>
        <source>main plane ZX</source>
        <translation>Hauptebene ZX</translation>
    </message>
    <message>
        <source>main plane YZ</source>
        <translation>Hauptebene YZ</translation>
    </message>
    <message>
        <source>work zone lower limits</source>
        <translation>untere Grenzen des Arbeitsbereichs</translation>
    </message>
    <message>
        <source>work zone upper limits</source>
        <translation>obere Grenzen des Arbeitsbereichs</translation>
    </message>
    <message>
        <source>work zone enable/disable</source>
        <translation>Arbeitsbereich ein/aus</translation>
    </message>
    <message>
        <source>feed as inverse of time</source>
        <translation>Vorschub als Kehrwert der Zeit</translation>
    </message>
    <message>
        <source>electronic threading</source>
        <translation>elektronisches Gewindeschneiden</translation>
    </message>
    <message>
        <source>variable-pitch threading</source>
        <translation>Gewindeschneiden mit variabler Steigung</translation>
    </message>
    <message>
        <source>corner rounding</source>
        <translation>Ecken verrunden</translation>
    </message>
    <message>
        <source>tangential entry</source>
        <translation>tangentiales Anfahren</translation>
    </message>
    <message>
        <source>tangential exit</source>
        <translation>tangentiales Abfahren</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>Fase</translation>
    </message>
    <message>
        <source>radius compensation off</source>
        <translation>Radiuskorrektur aus</translation>
    </message>
    <message>
        <source>radius compensation left</source>
        <translation>Radiuskorrektur links</translation>
    </message>
    <message>
        <source>radius compensation right</source>
        <translation>Radiuskorrektur rechts</translation>
    </message>
    <message>
        <source>inclined-axis transformation</source>
        <translation>Schrägachsen-Transformation</translation>
    </message>
    <message>
        <source>controlled round corner</source>
        <translation>gesteuerte verrundete Ecke</translation>
    </message>
    <message>
        <source>look-ahead</source>
        <translation>Look-Ahead (Vorausschau)</translation>
    </message>
    <message>
        <source>move to hard stop</source>
        <translation>Fahren auf Festanschlag</translation>
    </message>
    <message>
        <source>coordinates from machine zero</source>
        <translation>Koordinaten bezogen auf den Maschinen-Nullpunkt</translation>
    </message>
    <message>
        <source>absolute zero offset 1</source>
        <translation>absolute Nullpunktverschiebung 1</translation>
    </message>
    <message>
        <source>absolute zero offset 2</source>
        <translation>absolute Nullpunktverschiebung 2</translation>
    </message>
    <message>
        <source>absolute zero offset 3</source>
        <translation>absolute Nullpunktverschiebung 3</translation>
    </message>
    <message>
        <source>absolute zero offset 4</source>
        <translation>absolute Nullpunktverschiebung 4</translation>
    </message>
    <message>
        <source>additive zero offset 1</source>
        <translation>additive Nullpunktverschiebung 1</translation>
    </message>
    <message>
        <source>additive zero offset 2</source>
        <translation>additive Nullpunktverschiebung 2</translation>
    </message>
    <message>
        <source>pattern repeat cycle</source>
        <translation>Zyklus konturparalleles Abspanen</translation>
    </message>
    <message>
        <source>stock removal cycle along X</source>
        <translation>Abspanzyklus entlang X</translation>
    </message>
    <message>
        <source>stock removal cycle along Z</source>
        <translation>Abspanzyklus entlang Z</translation>
    </message>
    <message>
        <source>programming in inches</source>
        <translation>Programmierung in Zoll</translation>
    </message>
    <message>
        <source>programming in millimetres</source>
        <translation>Programmierung in Millimeter</translation>
    </message>
    <message>
        <source>scaling factor</source>
        <translation>Maßfaktor</translation>
    </message>
    <message>
        <source>machine reference search</source>
        <translation>Referenzpunkt der Maschine anfahren</translation>
    </message>
    <message>
        <source>probing move until touching</source>
        <translation>Antastbewegung bis zur Berührung</translation>
    </message>
    <message>
        <source>probing move until no longer touching</source>
        <translation>Antastbewegung, bis die Berührung aufhört</translation>
    </message>
    <message>
        <source>turning cycle, straight sections</source>
        <translation>Drehzyklus, gerade Abschnitte</translation>
    </message>
    <message>
        <source>facing cycle, straight sections</source>
        <translation>Planzyklus, gerade Abschnitte</translation>
    </message>
    <message>
        <source>drilling cycle</source>
        <translation>Bohrzyklus</translation>
    </message>
    <message>
        <source>turning cycle, curved sections</source>
        <translation>Drehzyklus, gekrümmte Abschnitte</translation>
    </message>
    <message>
        <source>facing cycle, curved sections</source>
        <translation>Planzyklus, gekrümmte Abschnitte</translation>
    </message>
    <message>
        <source>longitudinal threading cycle</source>
        <translation>Längsgewindezyklus</translation>
    </message>
    <message>
        <source>face threading cycle</source>
        <translation>Plangewindezyklus</translation>
    </message>
    <message>
        <source>grooving cycle along X</source>
        <translation>Einstechzyklus entlang X</translation>
    </message>
    <message>
        <source>grooving cycle along Z</source>
        <translation>Einstechzyklus entlang Z</translation>
    </message>
    <message>
        <source>absolute programming</source>
        <translation>Absolutprogrammierung</translation>
    </message>
    <message>
        <source>incremental programming</source>
        <translation>Inkrementalprogrammierung</translation>
    </message>
    <message>
        <source>coordinate preset / spindle speed limit</source>
        <translation>Koordinaten-Voreinstellung / Spindeldrehzahl-Begrenzung</translation>
    </message>
    <message>
        <source>polar origin preset</source>
        <translation>Voreinstellung des Polarursprungs</translation>
    </message>
    <message>
        <source>feed per minute</source>
        <translation>Vorschub pro Minute</translation>
    </message>
    <message>
        <source>feed per revolution</source>
        <translation>Vorschub pro Umdrehung</translation>
    </message>
    <message>
        <source>constant surface speed</source>
        <translation>konstante Schnittgeschwindigkeit</translation>
    </message>
    <message>
        <source>spindle speed in rpm</source>
        <translation>Spindeldrehzahl in 1/min</translation>
    </message>
    <message>
        <source>X in diameter</source>
        <translation>X im Durchmesser</translation>
    </message>
    <message>
        <source>X in radius</source>
        <translation>X im Radius</translation>
    </message>
    <message>
        <source>absolute zero offset N1-N20</source>
        <translation>absolute Nullpunktverschiebung N1-N20</translation>
    </message>
    <message>
        <source>axis retraction when threading stops</source>
        <translation>Achsrückzug beim Anhalten des Gewindeschneidens</translation>
    </message>
    <message>
        <source>{1} does not exist on the 8035 T</source>
        <translation>{1} gibt es an der 8035 T nicht</translation>
    </message>
    <message>
        <source>{1} ({2}) is not supported</source>
        <translation>{1} ({2}) wird nicht unterstützt</translation>
    </message>
    <message>
        <source>incompatible G functions {1} and {2} (error 7)</source>
        <translation>unverträgliche G-Funktionen {1} und {2} (Fehler 7)</translation>
    </message>
    <message>
        <source>{1} must be alone in its block</source>
        <translation>{1} muss allein im Satz stehen</translation>
    </message>
    <message>
        <source>tool radius too large</source>
        <translation>Werkzeugradius zu groß</translation>
    </message>
    <message>
        <source>tool radius too large: the offset swallows this element</source>
        <translation>Werkzeugradius zu groß: die Korrektur verschluckt dieses Element</translation>
    </message>
    <message>
        <source>tool radius too large for this arc</source>
        <translation>Werkzeugradius zu groß für diesen Kreisbogen</translation>
    </message>
    <message>
        <source>G40 needs a straight line (G00 or G01)</source>
        <translation>G40 braucht eine Gerade (G00 oder G01)</translation>
    </message>
    <message>
        <source>48 blocks without motion in the plane under radius compensation</source>
        <translation>48 Sätze ohne Bewegung in der Ebene bei aktiver Radiuskorrektur</translation>
    </message>
    <message>
        <source>the move violates work zone 1</source>
        <translation>die Bewegung verletzt Arbeitsbereich 1</translation>
    </message>
    <message>
        <source>the move violates work zone 2</source>
        <translation>die Bewegung verletzt Arbeitsbereich 2</translation>
    </message>
    <message>
        <source>the move violates work zone 3</source>
        <translation>die Bewegung verletzt Arbeitsbereich 3</translation>
    </message>
    <message>
        <source>the move violates work zone 4</source>
        <translation>die Bewegung verletzt Arbeitsbereich 4</translation>
    </message>
    <message>
        <source>the move violates work zone 5</source>
        <translation>die Bewegung verletzt Arbeitsbereich 5</translation>
    </message>
    <message>
        <source>an arc cannot be scaled differently along the two axes of its plane (G72)</source>
        <translation>ein Kreisbogen kann in den beiden Achsen seiner Ebene nicht unterschiedlich skaliert werden (G72)</translation>
    </message>
    <message>
        <source>P{1}: an interrupt subroutine may only use global parameters</source>
        <translation>P{1}: ein Interrupt-Unterprogramm darf nur globale Parameter verwenden</translation>
    </message>
    <message>
        <source>P{1}: OEM parameters are only for programs with the O attribute</source>
        <translation>P{1}: OEM-Parameter sind nur für Programme mit dem Attribut O</translation>
    </message>
    <message>
        <source>P{1} does not exist (P0-P25, P100-P299, P1000-P1255, P2000-P2255)</source>
        <translation>P{1} existiert nicht (P0-P25, P100-P299, P1000-P1255, P2000-P2255)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; expected</source>
        <translation>&apos;{1}&apos; erwartet</translation>
    </message>
    <message>
        <source>{1} must be a whole number from {2} to {3}, not {4}</source>
        <translation>{1} muss eine ganze Zahl von {2} bis {3} sein, nicht {4}</translation>
    </message>
    <message>
        <source>a label has at most 8 digits</source>
        <translation>eine Marke hat höchstens 8 Stellen</translation>
    </message>
    <message>
        <source>text in quotes expected</source>
        <translation>Text in Anführungszeichen erwartet</translation>
    </message>
    <message>
        <source>missing closing quote</source>
        <translation>schließendes Anführungszeichen fehlt</translation>
    </message>
    <message>
        <source>empty high-level block</source>
        <translation>leerer Hochsprachen-Satz</translation>
    </message>
    <message>
        <source>IF cannot be nested</source>
        <translation>IF kann nicht verschachtelt werden</translation>
    </message>
    <message>
        <source>SUB cannot be the action of an IF</source>
        <translation>SUB kann nicht die Aktion eines IF sein</translation>
    </message>
    <message>
        <source>subroutine number 0-20000 expected after SUB</source>
        <translation>Unterprogrammnummer 0-20000 nach SUB erwartet</translation>
    </message>
    <message>
        <source>at most 26 assignments to different targets</source>
        <translation>höchstens 26 Zuweisungen an verschiedene Ziele</translation>
    </message>
    <message>
        <source>parameter or variable expected</source>
        <translation>Parameter oder Variable erwartet</translation>
    </message>
    <message>
        <source>a subroutine call passes local parameters (P0-P25, A-Z)</source>
        <translation>ein Unterprogrammaufruf übergibt lokale Parameter (P0-P25, A-Z)</translation>
    </message>
    <message>
        <source>&apos;=&apos; expected</source>
        <translation>&apos;=&apos; erwartet</translation>
    </message>
    <message>
        <source>a subroutine call passes local parameters P0-P25, not P{1}</source>
        <translation>ein Unterprogrammaufruf übergibt lokale Parameter P0-P25, nicht P{1}</translation>
    </message>
    <message>
        <source>error number expected</source>
        <translation>Fehlernummer erwartet</translation>
    </message>
    <message>
        <source>ERROR takes a number, a parameter P0-P299 or a text</source>
        <translation>ERROR nimmt eine Zahl, einen Parameter P0-P299 oder einen Text</translation>
    </message>
    <message>
        <source>CALL passes no parameters: use PCALL or MCALL</source>
        <translation>CALL übergibt keine Parameter: PCALL oder MCALL verwenden</translation>
    </message>
    <message>
        <source>at most 26 parameters</source>
        <translation>höchstens 26 Parameter</translation>
    </message>
    <message>
        <source>programs on a PC over DNC are not available: only programs in the NC root</source>
        <translation>Programme auf einem PC über DNC sind nicht verfügbar: nur Programme im NC-Verzeichnis</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in {2}</source>
        <translation>unerwartetes &apos;{1}&apos; in {2}</translation>
    </message>
    <message>
        <source>axis letter expected in REPOS</source>
        <translation>Achsbuchstabe in REPOS erwartet</translation>
    </message>
    <message>
        <source>too many axes in REPOS</source>
        <translation>zu viele Achsen in REPOS</translation>
    </message>
    <message>
        <source>INPUT expected</source>
        <translation>INPUT erwartet</translation>
    </message>
    <message>
        <source>DW expected</source>
        <translation>DW erwartet</translation>
    </message>
    <message>
        <source>SK expected</source>
        <translation>SK erwartet</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a row key</source>
        <translation>&apos;{1}&apos; ist kein Zeilenschlüssel</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a field (letters and a number)</source>
        <translation>&apos;{1}&apos; ist kein Feld (Buchstaben und eine Zahl)</translation>
    </message>
    <message>
        <source>row {1} appears twice</source>
        <translation>Zeile {1} kommt doppelt vor</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a tool offset (D0-D255)</source>
        <translation>&apos;{1}&apos; ist keine Werkzeugkorrektur (D0-D255)</translation>
    </message>
    <message>
        <source>unknown field &apos;{1}&apos; (X Z F R I K)</source>
        <translation>unbekanntes Feld &apos;{1}&apos; (X Z F R I K)</translation>
    </message>
    <message>
        <source>the location code F must be a whole number 0-9</source>
        <translation>der Lagecode F muss eine ganze Zahl 0-9 sein</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a tool (T&lt;number&gt;)</source>
        <translation>&apos;{1}&apos; ist kein Werkzeug (T&lt;Nummer&gt;)</translation>
    </message>
    <message>
        <source>unknown field &apos;{1}&apos; (D FAM NLIFE RLIFE NOSEA NOSEW CUTA)</source>
        <translation>unbekanntes Feld &apos;{1}&apos; (D FAM NLIFE RLIFE NOSEA NOSEW CUTA)</translation>
    </message>
    <message>
        <source>{1} must be a whole number 0-255</source>
        <translation>{1} muss eine ganze Zahl 0-255 sein</translation>
    </message>
    <message>
        <source>G159 selects offsets N1-N20</source>
        <translation>G159 wählt die Verschiebungen N1-N20</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; cannot be part of the ACTIVE selection</source>
        <translation>&apos;{1}&apos; kann nicht Teil der Auswahl ACTIVE sein</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a zero offset (G54-G59, G159N7-G159N20, PLC, ACTIVE)</source>
        <translation>&apos;{1}&apos; ist keine Nullpunktverschiebung (G54-G59, G159N7-G159N20, PLC, ACTIVE)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not an axis</source>
        <translation>&apos;{1}&apos; ist keine Achse</translation>
    </message>
    <message>
        <source>the feed rate must not be negative</source>
        <translation>der Vorschub darf nicht negativ sein</translation>
    </message>
    <message>
        <source>M function number expected</source>
        <translation>M-Funktionsnummer erwartet</translation>
    </message>
    <message>
        <source>too many M functions in one block</source>
        <translation>zu viele M-Funktionen in einem Satz</translation>
    </message>
    <message>
        <source>axis {1} is programmed twice</source>
        <translation>Achse {1} ist doppelt programmiert</translation>
    </message>
    <message>
        <source>DR+ or DR- expected</source>
        <translation>DR+ oder DR- erwartet</translation>
    </message>
    <message>
        <source>CR needs a radius R</source>
        <translation>CR braucht einen Radius R</translation>
    </message>
    <message>
        <source>the rounding radius must be positive</source>
        <translation>der Rundungsradius muss positiv sein</translation>
    </message>
    <message>
        <source>the chamfer length must be positive</source>
        <translation>die Fasenlänge muss positiv sein</translation>
    </message>
    <message>
        <source>FMAX is not allowed here</source>
        <translation>FMAX ist hier nicht erlaubt</translation>
    </message>
    <message>
        <source>LT, LN, CT or LCT expected after {1}</source>
        <translation>LT, LN, CT oder LCT nach {1} erwartet</translation>
    </message>
    <message>
        <source>REP must be between 0 and 65534</source>
        <translation>REP muss zwischen 0 und 65534 liegen</translation>
    </message>
    <message>
        <source>program name expected</source>
        <translation>Programmname erwartet</translation>
    </message>
    <message>
        <source>LBL or PGM expected after CALL</source>
        <translation>LBL oder PGM nach CALL erwartet</translation>
    </message>
    <message>
        <source>tool number out of range</source>
        <translation>Werkzeugnummer außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>the spindle speed must not be negative</source>
        <translation>die Spindeldrehzahl darf nicht negativ sein</translation>
    </message>
    <message>
        <source>CALL or DEF expected after TOOL</source>
        <translation>CALL oder DEF nach TOOL erwartet</translation>
    </message>
    <message>
        <source>PGM expected</source>
        <translation>PGM erwartet</translation>
    </message>
    <message>
        <source>MM or INCH expected</source>
        <translation>MM oder INCH erwartet</translation>
    </message>
    <message>
        <source>FORM expected</source>
        <translation>FORM erwartet</translation>
    </message>
    <message>
        <source>axis expected</source>
        <translation>Achse erwartet</translation>
    </message>
    <message>
        <source>0.1, 0.2 or CYLINDER expected</source>
        <translation>0.1, 0.2 oder CYLINDER erwartet</translation>
    </message>
    <message>
        <source>tool axis expected</source>
        <translation>Werkzeugachse erwartet</translation>
    </message>
    <message>
        <source>Q parameter expected</source>
        <translation>Q-Parameter erwartet</translation>
    </message>
    <message>
        <source>DECLARE STRING needs a QS parameter</source>
        <translation>DECLARE STRING braucht einen QS-Parameter</translation>
    </message>
    <message>
        <source>FN number expected</source>
        <translation>FN-Nummer erwartet</translation>
    </message>
    <message>
        <source>&apos;:&apos; expected after FN {1}</source>
        <translation>&apos;:&apos; nach FN {1} erwartet</translation>
    </message>
    <message>
        <source>square root of a negative number</source>
        <translation>Quadratwurzel aus einer negativen Zahl</translation>
    </message>
    <message>
        <source>&apos;IF&apos; expected</source>
        <translation>&apos;IF&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;GOTO&apos; expected</source>
        <translation>&apos;GOTO&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;LBL&apos; expected</source>
        <translation>&apos;LBL&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;ERROR&apos; expected</source>
        <translation>&apos;ERROR&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;PRINT&apos; expected</source>
        <translation>&apos;PRINT&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;F-PRINT&apos; expected</source>
        <translation>&apos;F-PRINT&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;mask file / output file&apos; expected</source>
        <translation>&apos;Maskendatei / Ausgabedatei&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;SYSREAD&apos; expected</source>
        <translation>&apos;SYSREAD&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;ID&apos; expected</source>
        <translation>&apos;ID&apos; erwartet</translation>
    </message>
    <message>
        <source>&apos;CDATA&apos; expected</source>
        <translation>&apos;CDATA&apos; erwartet</translation>
    </message>
    <message>
        <source>the parameter range runs past the last Q parameter</source>
        <translation>der Parameterbereich reicht über den letzten Q-Parameter hinaus</translation>
    </message>
    <message>
        <source>&apos;TABOPEN&apos; expected</source>
        <translation>&apos;TABOPEN&apos; erwartet</translation>
    </message>
    <message>
        <source>table name expected</source>
        <translation>Tabellenname erwartet</translation>
    </message>
    <message>
        <source>&apos;/&apos; expected</source>
        <translation>&apos;/&apos; erwartet</translation>
    </message>
    <message>
        <source>column names in quotes expected</source>
        <translation>Spaltennamen in Anführungszeichen erwartet</translation>
    </message>
    <message>
        <source>FN {1} does not exist</source>
        <translation>FN {1} existiert nicht</translation>
    </message>
    <message>
        <source>DEF or CALL expected after CYCL</source>
        <translation>DEF oder CALL nach CYCL erwartet</translation>
    </message>
    <message>
        <source>file name expected</source>
        <translation>Dateiname erwartet</translation>
    </message>
    <message>
        <source>unknown block &apos;CYCLE&apos; (the keyword is CYCL)</source>
        <translation>unbekannter Satz &apos;CYCLE&apos; (das Schlüsselwort ist CYCL)</translation>
    </message>
    <message>
        <source>unknown block &apos;{1}&apos;</source>
        <translation>unbekannter Satz &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>label name must not be empty</source>
        <translation>der Label-Name darf nicht leer sein</translation>
    </message>
    <message>
        <source>label expected</source>
        <translation>Label erwartet</translation>
    </message>
    <message>
        <source>label number or name expected</source>
        <translation>Label-Nummer oder -Name erwartet</translation>
    </message>
    <message>
        <source>label number must be between {1} and 65535</source>
        <translation>die Label-Nummer muss zwischen {1} und 65535 liegen</translation>
    </message>
    <message>
        <source>cycle number expected</source>
        <translation>Zyklusnummer erwartet</translation>
    </message>
    <message>
        <source>cycle parameter Qnnn= expected</source>
        <translation>Zyklusparameter Qnnn= erwartet</translation>
    </message>
    <message>
        <source>cycle parameter number expected</source>
        <translation>Nummer des Zyklusparameters erwartet</translation>
    </message>
    <message>
        <source>GLOBAL DEF group number expected</source>
        <translation>GLOBAL DEF-Gruppennummer erwartet</translation>
    </message>
    <message>
        <source>pattern element POS, ROW, PAT, FRAME, CIRC or PITCHCIRC expected</source>
        <translation>Musterelement POS, ROW, PAT, FRAME, CIRC oder PITCHCIRC erwartet</translation>
    </message>
    <message>
        <source>PATTERN DEF needs at least one pattern element</source>
        <translation>PATTERN DEF braucht mindestens ein Musterelement</translation>
    </message>
    <message>
        <source>Spindle?</source>
        <translation>Spindel ?</translation>
    </message>
    <message>
        <source>Tool axis is missing</source>
        <translation>Werkzeugachse fehlt</translation>
    </message>
    <message>
        <source>Tool radius too small</source>
        <translation>Werkzeug-Radius zu klein</translation>
    </message>
    <message>
        <source>Tool radius too large</source>
        <translation>Werkzeug-Radius zu groß</translation>
    </message>
    <message>
        <source>Range exceeded</source>
        <translation>Bereich überschritten</translation>
    </message>
    <message>
        <source>Start position incorrect</source>
        <translation>Anfangsposition falsch</translation>
    </message>
    <message>
        <source>ROTATION not permitted</source>
        <translation>DREHUNG nicht erlaubt</translation>
    </message>
    <message>
        <source>SCALING FACTOR not permitted</source>
        <translation>MASSFAKTOR nicht erlaubt</translation>
    </message>
    <message>
        <source>MIRROR IMAGE not permitted</source>
        <translation>SPIEGELUNG nicht erlaubt</translation>
    </message>
    <message>
        <source>Datum shift not permitted</source>
        <translation>Verschiebung nicht erlaubt</translation>
    </message>
    <message>
        <source>Feed rate is missing</source>
        <translation>Vorschub fehlt</translation>
    </message>
    <message>
        <source>Input value incorrect</source>
        <translation>Eingabewert falsch</translation>
    </message>
    <message>
        <source>Incorrect sign</source>
        <translation>Vorzeichen falsch</translation>
    </message>
    <message>
        <source>Entered angle not permitted</source>
        <translation>Winkel nicht erlaubt</translation>
    </message>
    <message>
        <source>Touch point inaccessible</source>
        <translation>Antastpunkt nicht erreichbar</translation>
    </message>
    <message>
        <source>Too many points</source>
        <translation>Zu viele Punkte</translation>
    </message>
    <message>
        <source>Contradictory input</source>
        <translation>Eingabe widersprüchlich</translation>
    </message>
    <message>
        <source>CYCL incomplete</source>
        <translation>CYCL unvollständig</translation>
    </message>
    <message>
        <source>Plane wrongly defined</source>
        <translation>Ebene falsch definiert</translation>
    </message>
    <message>
        <source>Wrong axis programmed</source>
        <translation>Falsche Achse programmiert</translation>
    </message>
    <message>
        <source>Wrong RPM</source>
        <translation>Falsche Drehzahl</translation>
    </message>
    <message>
        <source>Radius comp. undefined</source>
        <translation>Radius-Korrektur undefiniert</translation>
    </message>
    <message>
        <source>Rounding-off undefined</source>
        <translation>Rundung nicht definiert</translation>
    </message>
    <message>
        <source>Rounding radius too large</source>
        <translation>Rundungsradius zu groß</translation>
    </message>
    <message>
        <source>Program start undefined</source>
        <translation>Undefinierter Programmstart</translation>
    </message>
    <message>
        <source>Excessive nesting</source>
        <translation>Zu hohe Verschachtelung</translation>
    </message>
    <message>
        <source>Angle reference missing</source>
        <translation>Winkelbezug fehlt</translation>
    </message>
    <message>
        <source>No fixed cycle defined</source>
        <translation>Kein Bearbeitungszyklus definiert</translation>
    </message>
    <message>
        <source>Slot width too small</source>
        <translation>Nutbreite zu klein</translation>
    </message>
    <message>
        <source>Pocket too small</source>
        <translation>Tasche zu klein</translation>
    </message>
    <message>
        <source>Q202 not defined</source>
        <translation>Q202 nicht definiert</translation>
    </message>
    <message>
        <source>Q205 not defined</source>
        <translation>Q205 nicht definiert</translation>
    </message>
    <message>
        <source>Q218 must be greater than Q219</source>
        <translation>Q218 muss größer als Q219 sein</translation>
    </message>
    <message>
        <source>CYCL 210 not permitted</source>
        <translation>CYCL 210 nicht erlaubt</translation>
    </message>
    <message>
        <source>CYCL 211 not permitted</source>
        <translation>CYCL 211 nicht erlaubt</translation>
    </message>
    <message>
        <source>Q220 too large</source>
        <translation>Q220 zu groß</translation>
    </message>
    <message>
        <source>Q222 must be greater than Q223</source>
        <translation>Q222 muss größer als Q223 sein</translation>
    </message>
    <message>
        <source>Q244 must be greater than 0</source>
        <translation>Q244 muss größer als 0 sein</translation>
    </message>
    <message>
        <source>Q245 must not equal Q246</source>
        <translation>Q245 darf nicht gleich Q246 sein</translation>
    </message>
    <message>
        <source>Angle range must be under 360 degrees</source>
        <translation>Winkelbereich muss unter 360 Grad liegen</translation>
    </message>
    <message>
        <source>Q223 must be greater than Q222</source>
        <translation>Q223 muss größer als Q222 sein</translation>
    </message>
    <message>
        <source>Q214: 0 not permitted</source>
        <translation>Q214: 0 nicht erlaubt</translation>
    </message>
    <message>
        <source>Traverse direction not defined</source>
        <translation>Verfahrrichtung nicht definiert</translation>
    </message>
    <message>
        <source>No datum table active</source>
        <translation>Keine Nullpunkt-Tabelle aktiv</translation>
    </message>
    <message>
        <source>Position error: center in axis 1</source>
        <translation>Lagefehler: Mitte Achse 1</translation>
    </message>
    <message>
        <source>Position error: center in axis 2</source>
        <translation>Lagefehler: Mitte Achse 2</translation>
    </message>
    <message>
        <source>Hole diameter too small</source>
        <translation>Bohrungsdurchmesser zu klein</translation>
    </message>
    <message>
        <source>Hole diameter too large</source>
        <translation>Bohrungsdurchmesser zu groß</translation>
    </message>
    <message>
        <source>Stud diameter too small</source>
        <translation>Zapfendurchmesser zu klein</translation>
    </message>
    <message>
        <source>Stud diameter too large</source>
        <translation>Zapfendurchmesser zu groß</translation>
    </message>
    <message>
        <source>Pocket too small: rework axis 1</source>
        <translation>Tasche zu klein: Nacharbeit Achse 1</translation>
    </message>
    <message>
        <source>Pocket too small: rework axis 2</source>
        <translation>Tasche zu klein: Nacharbeit Achse 2</translation>
    </message>
    <message>
        <source>Pocket too large: scrap axis 1</source>
        <translation>Tasche zu groß: Ausschuss Achse 1</translation>
    </message>
    <message>
        <source>Pocket too large: scrap axis 2</source>
        <translation>Tasche zu groß: Ausschuss Achse 2</translation>
    </message>
    <message>
        <source>Stud too small: scrap axis 1</source>
        <translation>Zapfen zu klein: Ausschuss Achse 1</translation>
    </message>
    <message>
        <source>Stud too small: scrap axis 2</source>
        <translation>Zapfen zu klein: Ausschuss Achse 2</translation>
    </message>
    <message>
        <source>Stud too large: rework axis 1</source>
        <translation>Zapfen zu groß: Nacharbeit Achse 1</translation>
    </message>
    <message>
        <source>Stud too large: rework axis 2</source>
        <translation>Zapfen zu groß: Nacharbeit Achse 2</translation>
    </message>
    <message>
        <source>TCHPROBE 425: length exceeds max</source>
        <translation>TCHPROBE 425: Größtmaß überschritten</translation>
    </message>
    <message>
        <source>TCHPROBE 425: length below min</source>
        <translation>TCHPROBE 425: Kleinstmaß unterschritten</translation>
    </message>
    <message>
        <source>TCHPROBE 426: length exceeds max</source>
        <translation>TCHPROBE 426: Größtmaß überschritten</translation>
    </message>
    <message>
        <source>TCHPROBE 426: length below min</source>
        <translation>TCHPROBE 426: Kleinstmaß unterschritten</translation>
    </message>
    <message>
        <source>TCHPROBE 430: diameter too large</source>
        <translation>TCHPROBE 430: Durchmesser zu groß</translation>
    </message>
    <message>
        <source>TCHPROBE 430: diameter too small</source>
        <translation>TCHPROBE 430: Durchmesser zu klein</translation>
    </message>
    <message>
        <source>No measuring axis defined</source>
        <translation>Keine Messachse definiert</translation>
    </message>
    <message>
        <source>Tool breakage tolerance exceeded</source>
        <translation>Werkzeug-Bruchtoleranz überschritten</translation>
    </message>
    <message>
        <source>Enter Q247 unequal 0</source>
        <translation>Q247 ungleich 0 eingeben</translation>
    </message>
    <message>
        <source>Enter Q247 greater than 5</source>
        <translation>Q247 größer 5 eingeben</translation>
    </message>
    <message>
        <source>Datum table?</source>
        <translation>Nullpunkt-Tabelle?</translation>
    </message>
    <message>
        <source>Enter Q351 unequal 0</source>
        <translation>Q351 ungleich 0 eingeben</translation>
    </message>
    <message>
        <source>Thread depth too large</source>
        <translation>Gewindetiefe zu groß</translation>
    </message>
    <message>
        <source>Missing calibration data</source>
        <translation>Kalibrierdaten fehlen</translation>
    </message>
    <message>
        <source>Tolerance exceeded</source>
        <translation>Toleranz überschritten</translation>
    </message>
    <message>
        <source>Block scan active</source>
        <translation>Satzvorlauf aktiv</translation>
    </message>
    <message>
        <source>ORIENTATION not permitted</source>
        <translation>ORIENTIERUNG nicht erlaubt</translation>
    </message>
    <message>
        <source>3DROT not permitted</source>
        <translation>3DROT nicht erlaubt</translation>
    </message>
    <message>
        <source>Activate 3DROT</source>
        <translation>3DROT aktivieren</translation>
    </message>
    <message>
        <source>Enter depth as negative</source>
        <translation>Tiefe negativ eingeben</translation>
    </message>
    <message>
        <source>Q303 not defined in measuring cycle</source>
        <translation>Q303 im Messzyklus undefiniert</translation>
    </message>
    <message>
        <source>Tool axis not allowed</source>
        <translation>Werkzeugachse nicht erlaubt</translation>
    </message>
    <message>
        <source>Calculated values incorrect</source>
        <translation>Berechnete Werte fehlerhaft</translation>
    </message>
    <message>
        <source>Contradictory measuring points</source>
        <translation>Messpunkte widersprüchlich</translation>
    </message>
    <message>
        <source>Incorrect clearance height</source>
        <translation>Sichere Höhe falsch eingegeben</translation>
    </message>
    <message>
        <source>Contradictory plunge type</source>
        <translation>Eintauchart widersprüchlich</translation>
    </message>
    <message>
        <source>This fixed cycle not allowed</source>
        <translation>Bearbeitungszyklus nicht erlaubt</translation>
    </message>
    <message>
        <source>Line is write-protected</source>
        <translation>Zeile ist schreibgeschützt</translation>
    </message>
    <message>
        <source>Oversize greater than depth</source>
        <translation>Aufmaß größer als Tiefe</translation>
    </message>
    <message>
        <source>No point angle defined</source>
        <translation>Kein Spitzenwinkel definiert</translation>
    </message>
    <message>
        <source>Contradictory data</source>
        <translation>Daten widersprüchlich</translation>
    </message>
    <message>
        <source>Slot position 0 not allowed</source>
        <translation>Nutlage 0 nicht erlaubt</translation>
    </message>
    <message>
        <source>Enter an infeed not equal to 0</source>
        <translation>Zustellung ungleich 0 eingeben</translation>
    </message>
    <message>
        <source>{1} is not defined for this value</source>
        <translation>{1} ist für diesen Wert nicht definiert</translation>
    </message>
    <message>
        <source>a string parameter cannot be used as a number</source>
        <translation>ein String-Parameter kann nicht als Zahl verwendet werden</translation>
    </message>
    <message>
        <source>{1}{2} does not exist (0 to {3})</source>
        <translation>{1}{2} existiert nicht (0 bis {3})</translation>
    </message>
    <message>
        <source>number or Q parameter expected</source>
        <translation>Zahl oder Q-Parameter erwartet</translation>
    </message>
    <message>
        <source>incomplete formula</source>
        <translation>unvollständige Formel</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in formula</source>
        <translation>unerwartetes &apos;{1}&apos; in der Formel</translation>
    </message>
    <message>
        <source>string parameter QS expected</source>
        <translation>String-Parameter QS erwartet</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a number</source>
        <translation>&apos;{1}&apos; ist keine Zahl</translation>
    </message>
    <message>
        <source>&apos;||&apos; expected</source>
        <translation>&apos;||&apos; erwartet</translation>
    </message>
    <message>
        <source>SUBSTR needs BEG and LEN of at least 0</source>
        <translation>SUBSTR braucht BEG und LEN von mindestens 0</translation>
    </message>
    <message>
        <source>SYSSTR ID{1} NR{2} is not available</source>
        <translation>SYSSTR ID{1} NR{2} ist nicht verfügbar</translation>
    </message>
    <message>
        <source>string expected</source>
        <translation>Text erwartet</translation>
    </message>
    <message>
        <source>unknown keyword &apos;{1}&apos;</source>
        <translation>unbekanntes Schlüsselwort &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>the format has no closing quote</source>
        <translation>dem Format fehlt das schließende Anführungszeichen</translation>
    </message>
    <message>
        <source>unknown value &apos;{1}&apos;</source>
        <translation>unbekannter Wert &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>bad format field</source>
        <translation>fehlerhaftes Formatfeld</translation>
    </message>
    <message>
        <source>more fields than values</source>
        <translation>mehr Felder als Werte</translation>
    </message>
    <message>
        <source>a cycle cannot be called with radius compensation RL/RR: program R0</source>
        <translation>ein Zyklus kann nicht mit Radiuskorrektur RL/RR aufgerufen werden: R0 programmieren</translation>
    </message>
    <message>
        <source>the cycle calls of this block need more than {1} moves</source>
        <translation>die Zyklusaufrufe dieses Satzes brauchen mehr als {1} Bewegungen</translation>
    </message>
    <message>
        <source>no machining cycle is defined (CYCL DEF)</source>
        <translation>kein Bearbeitungszyklus definiert (CYCL DEF)</translation>
    </message>
    <message>
        <source>CYCL CALL PAT: no PATTERN DEF or point table (SEL PATTERN) is active</source>
        <translation>CYCL CALL PAT: kein PATTERN DEF und keine Punkte-Tabelle (SEL PATTERN) aktiv</translation>
    </message>
    <message>
        <source>CYCL CALL PAT cannot use FMAX (without F it moves at rapid)</source>
        <translation>CYCL CALL PAT kann FMAX nicht verwenden (ohne F wird im Eilgang gefahren)</translation>
    </message>
    <message>
        <source>CYCL CALL POS needs all three coordinates</source>
        <translation>CYCL CALL POS braucht alle drei Koordinaten</translation>
    </message>
    <message>
        <source>cycle {1} needs a machining cycle defined before it</source>
        <translation>Zyklus {1} braucht einen zuvor definierten Bearbeitungszyklus</translation>
    </message>
    <message>
        <source>cycle {1} cannot call cycle {2}</source>
        <translation>Zyklus {1} kann Zyklus {2} nicht aufrufen</translation>
    </message>
    <message>
        <source>{1} has no parameter Q{2}: it is ignored</source>
        <translation>{1} hat keinen Parameter Q{2}: er wird ignoriert</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) is missing</source>
        <translation>{1}: Parameter {2} ({3}) fehlt</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) needs a text in quotes or a QS parameter</source>
        <translation>{1}: Parameter {2} ({3}) braucht einen Text in Anführungszeichen oder einen QS-Parameter</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) does not accept {4}</source>
        <translation>{1}: Parameter {2} ({3}) akzeptiert {4} nicht</translation>
    </message>
    <message>
        <source>FAUTO: the TOOL CALL block gave no feed rate F</source>
        <translation>FAUTO: der TOOL CALL-Satz hat keinen Vorschub F angegeben</translation>
    </message>
    <message>
        <source>{1}: {2} needs a feed value after {3}</source>
        <translation>{1}: {2} braucht einen Vorschubwert nach {3}</translation>
    </message>
    <message>
        <source>FZ needs the number of teeth (CUT) of the tool</source>
        <translation>FZ braucht die Schneidenanzahl (CUT) des Werkzeugs</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = &apos;{4}&apos; is not a value</source>
        <translation>{1}: Parameter {2} ({3}) = &apos;{4}&apos; ist kein Wert</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = {4} must be a whole number from {5} to {6}</source>
        <translation>{1}: Parameter {2} ({3}) = {4} muss eine ganze Zahl von {5} bis {6} sein</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = {4} is outside {5} to {6}</source>
        <translation>{1}: Parameter {2} ({3}) = {4} liegt außerhalb {5} bis {6}</translation>
    </message>
    <message>
        <source>cycle {1} is not supported yet</source>
        <translation>Zyklus {1} wird noch nicht unterstützt</translation>
    </message>
    <message>
        <source>CYCL DEF {1}.{2} without CYCL DEF {1}.0 before it</source>
        <translation>CYCL DEF {1}.{2} ohne vorheriges CYCL DEF {1}.0</translation>
    </message>
    <message>
        <source>GLOBAL DEF {1} does not exist</source>
        <translation>GLOBAL DEF {1} existiert nicht</translation>
    </message>
    <message>
        <source>cannot read the datum table {1}: {2}</source>
        <translation>die Nullpunkt-Tabelle {1} kann nicht gelesen werden: {2}</translation>
    </message>
    <message>
        <source>cannot read the point table {1}: {2}</source>
        <translation>die Punkte-Tabelle {1} kann nicht gelesen werden: {2}</translation>
    </message>
    <message>
        <source>{1} is not supported yet</source>
        <translation>{1} wird noch nicht unterstützt</translation>
    </message>
    <message>
        <source>FN 14 error {1}: {2}</source>
        <translation>FN 14 Fehler {1}: {2}</translation>
    </message>
    <message>
        <source>FN 14 error {1}</source>
        <translation>FN 14 Fehler {1}</translation>
    </message>
    <message>
        <source>cannot read the F-PRINT mask {1}</source>
        <translation>die F-PRINT-Maske {1} kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>F-PRINT mask {1} has an error</source>
        <translation>die F-PRINT-Maske {1} enthält einen Fehler</translation>
    </message>
    <message>
        <source>cannot write {1}</source>
        <translation>{1} kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>FN 18: SYSREAD ID{1} NR{2} IDX{3} is not available</source>
        <translation>FN 18: SYSREAD ID{1} NR{2} IDX{3} ist nicht verfügbar</translation>
    </message>
    <message>
        <source>FN {1}: the points do not define a circle</source>
        <translation>FN {1}: die Punkte definieren keinen Kreis</translation>
    </message>
    <message>
        <source>FN 26: cannot open table {1}</source>
        <translation>FN 26: Tabelle {1} kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>no table is open (FN 26: TABOPEN)</source>
        <translation>keine Tabelle geöffnet (FN 26: TABOPEN)</translation>
    </message>
    <message>
        <source>FN 27: cannot write row {1}</source>
        <translation>FN 27: Zeile {1} kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>FN 28: cannot read row {1}</source>
        <translation>FN 28: Zeile {1} kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>cannot read the program: {1}</source>
        <translation>das Programm kann nicht gelesen werden: {1}</translation>
    </message>
    <message>
        <source>label {1} is not defined</source>
        <translation>Label {1} ist nicht definiert</translation>
    </message>
    <message>
        <source>subprograms nested deeper than {1} levels</source>
        <translation>Unterprogramme tiefer als {1} Ebenen verschachtelt</translation>
    </message>
    <message>
        <source>program calls nested deeper than {1} levels</source>
        <translation>Programmaufrufe tiefer als {1} Ebenen verschachtelt</translation>
    </message>
    <message>
        <source>cannot call program {1}: {2}</source>
        <translation>Programm {1} kann nicht aufgerufen werden: {2}</translation>
    </message>
    <message>
        <source>the called program {1} has errors</source>
        <translation>das aufgerufene Programm {1} enthält Fehler</translation>
    </message>
    <message>
        <source>feed rate is missing</source>
        <translation>Vorschub fehlt</translation>
    </message>
    <message>
        <source>M140 MB MAX: the tool axis has no limit</source>
        <translation>M140 MB MAX: die Werkzeugachse hat keine Begrenzung</translation>
    </message>
    <message>
        <source>tool {1} is not in the tool table</source>
        <translation>Werkzeug {1} ist nicht in der Werkzeugtabelle</translation>
    </message>
    <message>
        <source>no tool table: tool {1} and the following tools are used with length 0 and radius 0</source>
        <translation>keine Werkzeugtabelle: Werkzeug {1} und die folgenden werden mit Länge 0 und Radius 0 verwendet</translation>
    </message>
    <message>
        <source>tool {1} is locked (TL)</source>
        <translation>Werkzeug {1} ist gesperrt (TL)</translation>
    </message>
    <message>
        <source>spindle speed {1} exceeds the machine&apos;s {2} rpm</source>
        <translation>Spindeldrehzahl {1} überschreitet die {2} 1/min der Maschine</translation>
    </message>
    <message>
        <source>BLK FORM 0.2 needs BLK FORM 0.1 before it</source>
        <translation>BLK FORM 0.2 braucht zuvor BLK FORM 0.1</translation>
    </message>
    <message>
        <source>the blank has no volume</source>
        <translation>das Rohteil hat kein Volumen</translation>
    </message>
    <message>
        <source>CC axes {1} and {2} do not span a plane</source>
        <translation>die CC-Achsen {1} und {2} spannen keine Ebene auf</translation>
    </message>
    <message>
        <source>CC takes two coordinates of a plane</source>
        <translation>CC nimmt zwei Koordinaten einer Ebene</translation>
    </message>
    <message>
        <source>circular moves cannot use FMAX</source>
        <translation>Kreisbewegungen können FMAX nicht verwenden</translation>
    </message>
    <message>
        <source>direction of rotation DR+ or DR- missing</source>
        <translation>Drehsinn DR+ oder DR- fehlt</translation>
    </message>
    <message>
        <source>no circle of radius {1} passes through the start and end point</source>
        <translation>kein Kreis mit Radius {1} geht durch Start- und Endpunkt</translation>
    </message>
    <message>
        <source>circle centre CC is not defined</source>
        <translation>der Kreismittelpunkt CC ist nicht definiert</translation>
    </message>
    <message>
        <source>the end point is not on the circle: radius {1} at the start, {2} at the end</source>
        <translation>der Endpunkt liegt nicht auf dem Kreis: Radius {1} am Anfang, {2} am Ende</translation>
    </message>
    <message>
        <source>a tangential arc needs a contour element before it</source>
        <translation>ein tangentialer Kreisbogen braucht ein vorheriges Konturelement</translation>
    </message>
    <message>
        <source>pole CC is not defined</source>
        <translation>der Pol CC ist nicht definiert</translation>
    </message>
    <message>
        <source>the end point lies on the tangent: no arc possible</source>
        <translation>der Endpunkt liegt auf der Tangente: kein Kreisbogen möglich</translation>
    </message>
    <message>
        <source>CP needs a polar angle PA or IPA</source>
        <translation>CP braucht einen Polarwinkel PA oder IPA</translation>
    </message>
    <message>
        <source>the sign of IPA does not match DR</source>
        <translation>das Vorzeichen von IPA passt nicht zu DR</translation>
    </message>
    <message>
        <source>{1} needs a positive length LEN</source>
        <translation>{1} braucht eine positive Länge LEN</translation>
    </message>
    <message>
        <source>{1} CT needs an angle CCA (0 to 360) and a radius R</source>
        <translation>{1} CT braucht einen Winkel CCA (0 bis 360) und einen Radius R</translation>
    </message>
    <message>
        <source>{1} LCT needs a radius R</source>
        <translation>{1} LCT braucht einen Radius R</translation>
    </message>
    <message>
        <source>APPR needs radius compensation RL or RR</source>
        <translation>APPR braucht die Radiuskorrektur RL oder RR</translation>
    </message>
    <message>
        <source>DEP LCT needs the end point</source>
        <translation>DEP LCT braucht den Endpunkt</translation>
    </message>
    <message>
        <source>an arc in the {1} plane cannot be rotated out of its plane or scaled with different factors</source>
        <translation>ein Kreisbogen in der {1}-Ebene kann nicht aus seiner Ebene gedreht oder mit verschiedenen Faktoren skaliert werden</translation>
    </message>
    <message>
        <source>cycle 7: no datum table selected (SEL TABLE)</source>
        <translation>Zyklus 7: keine Nullpunkt-Tabelle gewählt (SEL TABLE)</translation>
    </message>
    <message>
        <source>cycle 7: datum {1} is not in the datum table</source>
        <translation>Zyklus 7: Nullpunkt {1} ist nicht in der Nullpunkt-Tabelle</translation>
    </message>
    <message>
        <source>cycle 8: the tool axis {1} cannot be mirrored; it is left out</source>
        <translation>Zyklus 8: die Werkzeugachse {1} kann nicht gespiegelt werden; sie wird ausgelassen</translation>
    </message>
    <message>
        <source>cycle 247: no preset table (PRESET.PR) to read preset {1} from</source>
        <translation>Zyklus 247: keine Bezugspunkttabelle (PRESET.PR), aus der Bezugspunkt {1} gelesen werden kann</translation>
    </message>
    <message>
        <source>cycle 247: preset {1} is not in the preset table</source>
        <translation>Zyklus 247: Bezugspunkt {1} ist nicht in der Bezugspunkttabelle</translation>
    </message>
    <message>
        <source>cycle {1}: {2} expected</source>
        <translation>Zyklus {1}: {2} erwartet</translation>
    </message>
    <message>
        <source>cycle 12: program name expected</source>
        <translation>Zyklus 12: Programmname erwartet</translation>
    </message>
    <message>
        <source>cycle 18 has no sub-block 18.{1}</source>
        <translation>Zyklus 18 hat keinen Teilsatz 18.{1}</translation>
    </message>
    <message>
        <source>cycle 32: unexpected &apos;{1}&apos;</source>
        <translation>Zyklus 32: unerwartetes &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>block number {1} is out of order (after {2})</source>
        <translation>Satznummer {1} ist nicht in Reihenfolge (nach {2})</translation>
    </message>
    <message>
        <source>BEGIN PGM must be the first block</source>
        <translation>BEGIN PGM muss der erste Satz sein</translation>
    </message>
    <message>
        <source>END PGM {1} does not match BEGIN PGM {2}</source>
        <translation>END PGM {1} passt nicht zu BEGIN PGM {2}</translation>
    </message>
    <message>
        <source>label {1} is defined twice</source>
        <translation>Label {1} ist doppelt definiert</translation>
    </message>
    <message>
        <source>{1} is not supported yet; the program cannot run past this block</source>
        <translation>{1} wird noch nicht unterstützt; das Programm kann nicht über diesen Satz hinaus laufen</translation>
    </message>
    <message>
        <source>cycle {1} is not supported yet; the program cannot run past this block</source>
        <translation>Zyklus {1} wird noch nicht unterstützt; das Programm kann nicht über diesen Satz hinaus laufen</translation>
    </message>
    <message>
        <source>block has no number while others have</source>
        <translation>Satz hat keine Nummer, während andere eine haben</translation>
    </message>
    <message>
        <source>the program has no BEGIN PGM block</source>
        <translation>das Programm hat keinen BEGIN PGM-Satz</translation>
    </message>
    <message>
        <source>the program has no END PGM block</source>
        <translation>das Programm hat keinen END PGM-Satz</translation>
    </message>
    <message>
        <source>expected QRn=value</source>
        <translation>QRn=Wert erwartet</translation>
    </message>
    <message>
        <source>a rounding or chamfer must be followed by a contour element in the working plane</source>
        <translation>auf eine Rundung oder Fase muss ein Konturelement in der Bearbeitungsebene folgen</translation>
    </message>
    <message>
        <source>a chamfer needs straight lines on both sides</source>
        <translation>eine Fase braucht auf beiden Seiten Geraden</translation>
    </message>
    <message>
        <source>the chamfer is longer than the adjacent element</source>
        <translation>die Fase ist länger als das angrenzende Element</translation>
    </message>
    <message>
        <source>the rounding radius does not fit between the elements</source>
        <translation>der Rundungsradius passt nicht zwischen die Elemente</translation>
    </message>
    <message>
        <source>a rounding needs a contour element before it</source>
        <translation>eine Rundung braucht ein vorheriges Konturelement</translation>
    </message>
    <message>
        <source>a chamfer needs a contour element before it</source>
        <translation>eine Fase braucht ein vorheriges Konturelement</translation>
    </message>
    <message>
        <source>a rounding or chamfer must be followed by a contour element</source>
        <translation>auf eine Rundung oder Fase muss ein Konturelement folgen</translation>
    </message>
    <message>
        <source>an approach must be followed by a compensated contour element</source>
        <translation>auf das Anfahren muss ein korrigiertes Konturelement folgen</translation>
    </message>
    <message>
        <source>an approach needs RL or RR</source>
        <translation>das Anfahren braucht RL oder RR</translation>
    </message>
    <message>
        <source>a departure needs a compensated contour element before it</source>
        <translation>das Abfahren braucht ein vorheriges korrigiertes Konturelement</translation>
    </message>
    <message>
        <source>the departure cannot be constructed with these values</source>
        <translation>das Abfahren lässt sich mit diesen Werten nicht konstruieren</translation>
    </message>
    <message>
        <source>leave radius compensation with a straight line</source>
        <translation>die Radiuskorrektur mit einer Geraden aufheben</translation>
    </message>
    <message>
        <source>switching between RL and RR needs a block with R0 between</source>
        <translation>der Wechsel zwischen RL und RR braucht einen Satz mit R0 dazwischen</translation>
    </message>
    <message>
        <source>radius compensation must begin with a straight line</source>
        <translation>die Radiuskorrektur muss mit einer Geraden beginnen</translation>
    </message>
    <message>
        <source>the approach cannot be constructed with these values</source>
        <translation>das Anfahren lässt sich mit diesen Werten nicht konstruieren</translation>
    </message>
    <message>
        <source>base = {1} is not a built-in machine ({2})</source>
        <translation>base = {1} ist keine eingebaute Maschine ({2})</translation>
    </message>
    <message>
        <source>{1} must be a table</source>
        <translation>{1} muss eine Tabelle sein</translation>
    </message>
    <message>
        <source>axes must be a table of axes such as [axes.X]</source>
        <translation>axes muss eine Tabelle von Achsen sein, etwa [axes.X]</translation>
    </message>
    <message>
        <source>{1}: {2} is not an axis letter; use one of {3}</source>
        <translation>{1}: {2} ist kein Achsbuchstabe; einen von {3} verwenden</translation>
    </message>
    <message>
        <source>{1} is a table; expected {2}</source>
        <translation>{1} ist eine Tabelle; erwartet wurde {2}</translation>
    </message>
    <message>
        <source>{1} = {2} is {3}; expected {4}</source>
        <translation>{1} = {2} ist {3}; erwartet wurde {4}</translation>
    </message>
    <message>
        <source>unknown key {1}</source>
        <translation>unbekannter Schlüssel {1}</translation>
    </message>
    <message>
        <source>unknown key {1}; did you mean {2}?</source>
        <translation>unbekannter Schlüssel {1}; war {2} gemeint?</translation>
    </message>
    <message>
        <source>TOML syntax error: {1}</source>
        <translation>TOML-Syntaxfehler: {1}</translation>
    </message>
    <message>
        <source>cannot read the machine configuration: {1}</source>
        <translation>die Maschinenkonfiguration kann nicht gelesen werden: {1}</translation>
    </message>
    <message>
        <source>Name shown to the operator</source>
        <translation>Name, der dem Bediener angezeigt wird</translation>
    </message>
    <message>
        <source>Machine kind; selects the program dialects and lathe conventions</source>
        <translation>Maschinenart; wählt die Programmdialekte und die Drehmaschinen-Konventionen</translation>
    </message>
    <message>
        <source>Axis the tool points along; tool length compensation acts on it</source>
        <translation>Achse, in die das Werkzeug zeigt; auf sie wirkt die Werkzeuglängenkorrektur</translation>
    </message>
    <message>
        <source>Path velocity of rapid moves</source>
        <translation>Bahngeschwindigkeit der Eilgangbewegungen</translation>
    </message>
    <message>
        <source>Highest programmable feed rate</source>
        <translation>Höchster programmierbarer Vorschub</translation>
    </message>
    <message>
        <source>Period of the servo cycle</source>
        <translation>Periode des Servo-Zyklus</translation>
    </message>
    <message>
        <source>Default path deviation allowed when blending corners; 0 stops exactly</source>
        <translation>Standard-Bahnabweichung beim Überschleifen von Ecken; 0 hält genau an</translation>
    </message>
    <message>
        <source>Lowest spindle speed</source>
        <translation>Kleinste Spindeldrehzahl</translation>
    </message>
    <message>
        <source>Highest spindle speed</source>
        <translation>Größte Spindeldrehzahl</translation>
    </message>
    <message>
        <source>CANopen node-ID of the spindle drive; 0: the spindle has none</source>
        <translation>CANopen-Node-ID des Spindelantriebs; 0: die Spindel hat keinen</translation>
    </message>
    <message>
        <source>Spindle drive position units per degree</source>
        <translation>Positionseinheiten des Spindelantriebs pro Grad</translation>
    </message>
    <message>
        <source>CiA 402 mode of the spindle drive: cyclic synchronous or profile velocity</source>
        <translation>CiA-402-Betriebsart des Spindelantriebs: zyklisch synchron oder Profilgeschwindigkeit</translation>
    </message>
    <message>
        <source>Lathe: diameter of the bar simulated when the program defines no blank; 0: none</source>
        <translation>Drehmaschine: Durchmesser der simulierten Stange, wenn das Programm kein Rohteil definiert; 0: keine</translation>
    </message>
    <message>
        <source>Lathe: length of the simulated bar</source>
        <translation>Drehmaschine: Länge der simulierten Stange</translation>
    </message>
    <message>
        <source>Lathe: workpiece Z of the bar&apos;s face; the bar reaches down to face_z - length</source>
        <translation>Drehmaschine: Werkstück-Z der Stirnfläche der Stange; die Stange reicht bis face_z - length</translation>
    </message>
    <message>
        <source>Lathe: inner diameter of a tube; 0: a solid bar</source>
        <translation>Drehmaschine: Innendurchmesser eines Rohrs; 0: Vollstange</translation>
    </message>
    <message>
        <source>SocketCAN interface of the drive bus</source>
        <translation>SocketCAN-Schnittstelle des Antriebsbusses</translation>
    </message>
    <message>
        <source>Bit rate of the drive bus (a CiA 301 rate)</source>
        <translation>Bitrate des Antriebsbusses (eine CiA-301-Rate)</translation>
    </message>
    <message>
        <source>SYNC period of the drive bus; a whole multiple of servo_period</source>
        <translation>SYNC-Periode des Antriebsbusses; ein ganzzahliges Vielfaches von servo_period</translation>
    </message>
    <message>
        <source>Heartbeat period of every drive (0x1017)</source>
        <translation>Heartbeat-Periode jedes Antriebs (0x1017)</translation>
    </message>
    <message>
        <source>A drive whose heartbeat is missing this long is lost; above heartbeat_period</source>
        <translation>Ein Antrieb, dessen Heartbeat so lange ausbleibt, gilt als verloren; größer als heartbeat_period</translation>
    </message>
    <message>
        <source>A drive whose feedback PDO is missing this many cycles is lost</source>
        <translation>Ein Antrieb, dessen Istwert-PDO so viele Zyklen ausbleibt, gilt als verloren</translation>
    </message>
    <message>
        <source>CANopen node-ID of the control&apos;s heartbeat, watched by the drives</source>
        <translation>CANopen-Node-ID des Heartbeats der Steuerung, von den Antrieben überwacht</translation>
    </message>
    <message>
        <source>Vendor-ID every drive must report (0x1018 sub 1), hexadecimal like 0x0000029C; empty: not checked</source>
        <translation>Vendor-ID, die jeder Antrieb melden muss (0x1018 Sub 1), hexadezimal wie 0x0000029C; leer: nicht geprüft</translation>
    </message>
    <message>
        <source>Product code every drive must report (0x1018 sub 2); empty: not checked</source>
        <translation>Produktcode, den jeder Antrieb melden muss (0x1018 Sub 2); leer: nicht geprüft</translation>
    </message>
    <message>
        <source>Linear or rotary; A, B and C default to rotary</source>
        <translation>Linear oder rotatorisch; A, B und C sind standardmäßig Drehachsen</translation>
    </message>
    <message>
        <source>Lower soft limit in machine coordinates (a radius on a lathe)</source>
        <translation>Unterer Software-Endschalter in Maschinenkoordinaten (an einer Drehmaschine ein Radius)</translation>
    </message>
    <message>
        <source>Upper soft limit in machine coordinates (a radius on a lathe)</source>
        <translation>Oberer Software-Endschalter in Maschinenkoordinaten (an einer Drehmaschine ein Radius)</translation>
    </message>
    <message>
        <source>Highest velocity of the axis</source>
        <translation>Höchste Geschwindigkeit der Achse</translation>
    </message>
    <message>
        <source>Highest acceleration of the axis</source>
        <translation>Höchste Beschleunigung der Achse</translation>
    </message>
    <message>
        <source>Highest jerk of the axis</source>
        <translation>Höchster Ruck der Achse</translation>
    </message>
    <message>
        <source>Machine position after homing; must lie within the soft limits</source>
        <translation>Maschinenposition nach dem Referenzfahren; muss innerhalb der Software-Endschalter liegen</translation>
    </message>
    <message>
        <source>The axis may be absent and is then switched off with enabled = false</source>
        <translation>Die Achse darf fehlen und wird dann mit enabled = false abgeschaltet</translation>
    </message>
    <message>
        <source>The axis is present; only optional axes may be disabled</source>
        <translation>Die Achse ist vorhanden; nur optionale Achsen dürfen abgeschaltet werden</translation>
    </message>
    <message>
        <source>Lathe: the axis is programmed and displayed as a diameter</source>
        <translation>Drehmaschine: die Achse wird im Durchmesser programmiert und angezeigt</translation>
    </message>
    <message>
        <source>CANopen node-ID of the axis drive; 0: none</source>
        <translation>CANopen-Node-ID des Achsantriebs; 0: keiner</translation>
    </message>
    <message>
        <source>Drive position units per millimetre or degree</source>
        <translation>Positionseinheiten des Antriebs pro Millimeter oder Grad</translation>
    </message>
    <message>
        <source>Following error the drive allows (0x6065) before it faults</source>
        <translation>Schleppfehler, den der Antrieb zulässt (0x6065), bevor er auf Fehler geht</translation>
    </message>
    <message>
        <source>the machine has no axis for {1}</source>
        <translation>die Maschine hat keine Achse für {1}</translation>
    </message>
    <message>
        <source>{1} = {2} must be less than {3} = {4}</source>
        <translation>{1} = {2} muss kleiner sein als {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the soft limits {3} … {4} {5}</source>
        <translation>{1} = {2} liegt außerhalb der Software-Endschalter {3} … {4} {5}</translation>
    </message>
    <message>
        <source>{1} = false is only allowed when {2} = true</source>
        <translation>{1} = false ist nur erlaubt, wenn {2} = true</translation>
    </message>
    <message>
        <source>{1} = true is only allowed on a linear axis of a lathe</source>
        <translation>{1} = true ist nur an einer Linearachse einer Drehmaschine erlaubt</translation>
    </message>
    <message>
        <source>the machine has no axes; add [axes.X] tables or start from a built-in machine with base = &quot;mill&quot;</source>
        <translation>die Maschine hat keine Achsen; Tabellen [axes.X] hinzufügen oder von einer eingebauten Maschine mit base = &quot;mill&quot; ausgehen</translation>
    </message>
    <message>
        <source>axis letter {1} is not one of {2}</source>
        <translation>Achsbuchstabe {1} ist keiner von {2}</translation>
    </message>
    <message>
        <source>axis {1} is listed twice</source>
        <translation>Achse {1} ist doppelt aufgeführt</translation>
    </message>
    <message>
        <source>tool_axis = {1} is not an enabled axis of this machine ({2})</source>
        <translation>tool_axis = {1} ist keine aktive Achse dieser Maschine ({2})</translation>
    </message>
    <message>
        <source>tool_axis = {1} must be a linear axis</source>
        <translation>tool_axis = {1} muss eine Linearachse sein</translation>
    </message>
    <message>
        <source>{1} = {2} must not exceed {3} = {4}</source>
        <translation>{1} = {2} darf {3} = {4} nicht überschreiten</translation>
    </message>
    <message>
        <source>{1} = {2} must be smaller than {3} = {4}</source>
        <translation>{1} = {2} muss kleiner sein als {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} is the node-ID of drives.master_node</source>
        <translation>{1} = {2} ist die Node-ID von drives.master_node</translation>
    </message>
    <message>
        <source>{1} = {2} is already the node of {3}</source>
        <translation>{1} = {2} ist bereits der Knoten von {3}</translation>
    </message>
    <message>
        <source>drives.cycle_period = {1} must be a whole multiple of servo_period = {2}</source>
        <translation>drives.cycle_period = {1} muss ein ganzzahliges Vielfaches von servo_period = {2} sein</translation>
    </message>
    <message>
        <source>drives.heartbeat_timeout = {1} must exceed drives.heartbeat_period = {2}</source>
        <translation>drives.heartbeat_timeout = {1} muss größer sein als drives.heartbeat_period = {2}</translation>
    </message>
    <message>
        <source>drives.bitrate = {1} is not a CiA 301 bit rate (10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)</source>
        <translation>drives.bitrate = {1} ist keine CiA-301-Bitrate (10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)</translation>
    </message>
    <message>
        <source>{1} = &quot;{2}&quot; is not a 32-bit number such as 0x0000029C</source>
        <translation>{1} = &quot;{2}&quot; ist keine 32-Bit-Zahl wie 0x0000029C</translation>
    </message>
    <message>
        <source>{1} = {2} has the wrong type; expected {3}</source>
        <translation>{1} = {2} hat den falschen Typ; erwartet wurde {3}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the allowed range {3}</source>
        <translation>{1} = {2} liegt außerhalb des zulässigen Bereichs {3}</translation>
    </message>
    <message>
        <source>{1} = {2} is not one of {3}</source>
        <translation>{1} = {2} ist keiner der Werte {3}</translation>
    </message>
    <message>
        <source>empty file name</source>
        <translation>leerer Dateiname</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is outside the NC root</source>
        <translation>&apos;{1}&apos; liegt außerhalb des NC-Verzeichnisses</translation>
    </message>
    <message>
        <source>datum {1} is not in the datum table</source>
        <translation>Nullpunkt {1} ist nicht in der Nullpunkt-Tabelle</translation>
    </message>
    <message>
        <source>datum {1} is already in the datum table</source>
        <translation>Nullpunkt {1} ist bereits in der Nullpunkt-Tabelle</translation>
    </message>
    <message>
        <source>the table does not start with a BEGIN line</source>
        <translation>die Tabelle beginnt nicht mit einer BEGIN-Zeile</translation>
    </message>
    <message>
        <source>the BEGIN line names no table</source>
        <translation>die BEGIN-Zeile nennt keine Tabelle</translation>
    </message>
    <message>
        <source>the BEGIN line gives no file type</source>
        <translation>die BEGIN-Zeile nennt keinen Dateityp</translation>
    </message>
    <message>
        <source>the table has no column {1}</source>
        <translation>die Tabelle hat keine Spalte {1}</translation>
    </message>
    <message>
        <source>column {1} needs a whole number &gt;= 0, not &quot;{2}&quot;</source>
        <translation>Spalte {1} braucht eine ganze Zahl &gt;= 0, nicht &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>the table has no row {1}</source>
        <translation>die Tabelle hat keine Zeile {1}</translation>
    </message>
    <message>
        <source>the table has no column &quot;{1}&quot;</source>
        <translation>die Tabelle hat keine Spalte &quot;{1}&quot;</translation>
    </message>
    <message>
        <source>cell {1} of row {2} is empty</source>
        <translation>Zelle {1} von Zeile {2} ist leer</translation>
    </message>
    <message>
        <source>column {1} needs a number, not &quot;{2}&quot;</source>
        <translation>Spalte {1} braucht eine Zahl, nicht &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>{1} columns named but {2} values given</source>
        <translation>{1} Spalten benannt, aber {2} Werte angegeben</translation>
    </message>
    <message>
        <source>column {1} holds text, not numbers</source>
        <translation>Spalte {1} enthält Text, keine Zahlen</translation>
    </message>
    <message>
        <source>point {1} is not in the point table</source>
        <translation>Punkt {1} ist nicht in der Punkte-Tabelle</translation>
    </message>
    <message>
        <source>column {1} needs Y or nothing, not &quot;{2}&quot;</source>
        <translation>Spalte {1} braucht Y oder nichts, nicht &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>point {1} is already in the point table</source>
        <translation>Punkt {1} ist bereits in der Punkte-Tabelle</translation>
    </message>
    <message>
        <source>preset {1} is not in the preset table</source>
        <translation>Bezugspunkt {1} ist nicht in der Bezugspunkttabelle</translation>
    </message>
    <message>
        <source>preset {1} is already in the preset table</source>
        <translation>Bezugspunkt {1} ist bereits in der Bezugspunkttabelle</translation>
    </message>
    <message>
        <source>column {1} needs a whole number, not &quot;{2}&quot;</source>
        <translation>Spalte {1} braucht eine ganze Zahl, nicht &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>the key column {1} is empty</source>
        <translation>die Schlüsselspalte {1} ist leer</translation>
    </message>
    <message>
        <source>{1} {2} appears twice (first in line {3})</source>
        <translation>{1} {2} kommt doppelt vor (zuerst in Zeile {3})</translation>
    </message>
    <message>
        <source>the table has no column header line</source>
        <translation>die Tabelle hat keine Spaltenkopf-Zeile</translation>
    </message>
    <message>
        <source>the table has no cell at row {1}, column {2}</source>
        <translation>die Tabelle hat keine Zelle in Zeile {1}, Spalte {2}</translation>
    </message>
    <message>
        <source>a cell of column {1} cannot hold a line break</source>
        <translation>eine Zelle der Spalte {1} kann keinen Zeilenumbruch enthalten</translation>
    </message>
    <message>
        <source>{2} does not fit into column {1} ({3} characters)</source>
        <translation>{2} passt nicht in Spalte {1} ({3} Zeichen)</translation>
    </message>
    <message>
        <source>column {1} cannot hold an infinite number</source>
        <translation>Spalte {1} kann keine unendliche Zahl enthalten</translation>
    </message>
    <message>
        <source>cannot insert a row at {1}: the table has {2} rows</source>
        <translation>an Stelle {1} kann keine Zeile eingefügt werden: die Tabelle hat {2} Zeilen</translation>
    </message>
    <message>
        <source>&quot;{2}&quot; cannot be a key of column {1}</source>
        <translation>&quot;{2}&quot; kann kein Schlüssel der Spalte {1} sein</translation>
    </message>
    <message>
        <source>column {1} needs L, 1, 0 or nothing, not &quot;{2}&quot;</source>
        <translation>Spalte {1} braucht L, 1, 0 oder nichts, nicht &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>tool {1} is already in the tool table</source>
        <translation>Werkzeug {1} ist bereits in der Werkzeugtabelle</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>inaktiv</translation>
    </message>
    <message>
        <source>running</source>
        <translation>läuft</translation>
    </message>
    <message>
        <source>feed hold</source>
        <translation>Vorschub-Halt</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>gestoppt</translation>
    </message>
    <message>
        <source>waiting for the machine</source>
        <translation>wartet auf die Maschine</translation>
    </message>
    <message>
        <source>finished</source>
        <translation>beendet</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>motion refused the block: {1}</source>
        <translation>die Bewegungssteuerung hat den Satz abgelehnt: {1}</translation>
    </message>
    <message>
        <source>motion stopped: {1}</source>
        <translation>Bewegung angehalten: {1}</translation>
    </message>
    <message>
        <source>column {1} must be greater than 0, not {2}</source>
        <translation>Spalte {1} muss größer als 0 sein, nicht {2}</translation>
    </message>
    <message>
        <source>column {1} must not be negative, not {2}</source>
        <translation>Spalte {1} darf nicht negativ sein, nicht {2}</translation>
    </message>
    <message>
        <source>column {1} needs {2} or {3}, not &quot;{4}&quot;</source>
        <translation>Spalte {1} braucht {2} oder {3}, nicht &quot;{4}&quot;</translation>
    </message>
    <message>
        <source>{1} needs the coordinates of its end point</source>
        <translation>{1} braucht die Koordinaten seines Endpunkts</translation>
    </message>
    <message>
        <source>{1} is a straight probing move in workpiece coordinates: not with G06, G08, G09, G36-G39 or G53</source>
        <translation>{1} ist eine gerade Antastbewegung in Werkstück-Koordinaten: nicht mit G06, G08, G09, G36-G39 oder G53</translation>
    </message>
    <message>
        <source>G75 reached its end point without the probe touching</source>
        <translation>G75 hat den Endpunkt erreicht, ohne dass das Tastsystem berührt hat</translation>
    </message>
    <message>
        <source>G76 reached its end point with the probe still touching</source>
        <translation>G76 hat den Endpunkt erreicht, während das Tastsystem noch berührt</translation>
    </message>
    <message>
        <source>Simulation: a box-shaped workpiece the touch probe touches (G75, probing cycles); the bounds below, machine coordinates of the tool tip</source>
        <translation>Simulation: ein quaderförmiges Werkstück, das das Tastsystem berührt (G75, Tastsystemzyklen); die Grenzen unten in Maschinenkoordinaten der Werkzeugspitze</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine X of the tool tip inside it</source>
        <translation>Simuliertes Antast-Werkstück: kleinstes Maschinen-X der Werkzeugspitze darin</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine X of the tool tip inside it</source>
        <translation>Simuliertes Antast-Werkstück: größtes Maschinen-X der Werkzeugspitze darin</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine Y of the tool tip inside it</source>
        <translation>Simuliertes Antast-Werkstück: kleinstes Maschinen-Y der Werkzeugspitze darin</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine Y of the tool tip inside it</source>
        <translation>Simuliertes Antast-Werkstück: größtes Maschinen-Y der Werkzeugspitze darin</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine Z of the tool tip inside it</source>
        <translation>Simuliertes Antast-Werkstück: kleinstes Maschinen-Z der Werkzeugspitze darin</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine Z of the tool tip inside it</source>
        <translation>Simuliertes Antast-Werkstück: größtes Maschinen-Z der Werkzeugspitze darin</translation>
    </message>
    <message>
        <source>Machine coordinate of the workpiece origin (the default preset); kerf run --work-offset overrides it</source>
        <translation>Maschinenkoordinate des Werkstück-Nullpunkts (der Standard-Bezugspunkt); kerf run --work-offset ersetzt sie</translation>
    </message>
    <message>
        <source>{1} needs a programmed feed F greater than 0</source>
        <translation>{1} braucht einen programmierten Vorschub F größer als 0</translation>
    </message>
    <message>
        <source>Drilling/
thread</source>
        <translation>Bohren/
Gewinde</translation>
    </message>
    <message>
        <source>Pockets/
studs/slots</source>
        <translation>Taschen/
Zapfen/Nuten</translation>
    </message>
    <message>
        <source>Patterns</source>
        <translation>Muster</translation>
    </message>
    <message>
        <source>SL cycles</source>
        <translation>SL-Zyklen</translation>
    </message>
    <message>
        <source>Coordinate
transform.</source>
        <translation>Koordinaten-
umrechnung</translation>
    </message>
    <message>
        <source>Special
cycles</source>
        <translation>Sonder-
zyklen</translation>
    </message>
    <message>
        <source>SET-UP CLEARANCE</source>
        <translation>SICHERHEITS-ABST.</translation>
    </message>
    <message>
        <source>DEPTH</source>
        <translation>TIEFE</translation>
    </message>
    <message>
        <source>PLUNGING DEPTH</source>
        <translation>ZUSTELL-TIEFE</translation>
    </message>
    <message>
        <source>SURFACE COORDINATE</source>
        <translation>KOOR. OBERFLÄCHE</translation>
    </message>
    <message>
        <source>2ND SET-UP CLEARANCE</source>
        <translation>2. SICHERHEITS-ABST.</translation>
    </message>
    <message>
        <source>MIN. PLUNGING DEPTH</source>
        <translation>MIN. ZUSTELL-TIEFE</translation>
    </message>
    <message>
        <source>FEED RATE FOR PLNGNG</source>
        <translation>VORSCHUB TIEFENZUST.</translation>
    </message>
    <message>
        <source>FEED RATE FOR MILLING</source>
        <translation>VORSCHUB FRÄSEN</translation>
    </message>
    <message>
        <source>RETRACTION FEED RATE</source>
        <translation>VORSCHUB RÜCKZUG</translation>
    </message>
    <message>
        <source>DWELL TIME AT TOP</source>
        <translation>VERWEILZEIT OBEN</translation>
    </message>
    <message>
        <source>DWELL TIME AT DEPTH</source>
        <translation>VERWEILZEIT UNTEN</translation>
    </message>
    <message>
        <source>DECREMENT</source>
        <translation>ABNAHMEBETRAG</translation>
    </message>
    <message>
        <source>NR OF BREAKS</source>
        <translation>SPANBRÜCHE</translation>
    </message>
    <message>
        <source>DISENGAGING DIRECTN</source>
        <translation>FREIFAHR-RICHTUNG</translation>
    </message>
    <message>
        <source>CENTER IN 1ST AXIS</source>
        <translation>MITTE 1. ACHSE</translation>
    </message>
    <message>
        <source>CENTER IN 2ND AXIS</source>
        <translation>MITTE 2. ACHSE</translation>
    </message>
    <message>
        <source>FIRST SIDE LENGTH</source>
        <translation>1. SEITEN-LÄNGE</translation>
    </message>
    <message>
        <source>2ND SIDE LENGTH</source>
        <translation>2. SEITEN-LÄNGE</translation>
    </message>
    <message>
        <source>ANGLE OF ROTATION</source>
        <translation>DREHLAGE</translation>
    </message>
    <message>
        <source>STARTNG PNT 1ST AXIS</source>
        <translation>STARTPUNKT 1. ACHSE</translation>
    </message>
    <message>
        <source>STARTNG PNT 2ND AXIS</source>
        <translation>STARTPUNKT 2. ACHSE</translation>
    </message>
    <message>
        <source>STARTNG PNT 3RD AXIS</source>
        <translation>STARTPUNKT 3. ACHSE</translation>
    </message>
    <message>
        <source>SPACING IN 1ST AXIS</source>
        <translation>ABSTAND 1. ACHSE</translation>
    </message>
    <message>
        <source>SPACING IN 2ND AXIS</source>
        <translation>ABSTAND 2. ACHSE</translation>
    </message>
    <message>
        <source>THREAD PITCH</source>
        <translation>GEWINDESTEIGUNG</translation>
    </message>
    <message>
        <source>NR OF REPETITIONS</source>
        <translation>ANZ. WIEDERHOLUNGEN</translation>
    </message>
    <message>
        <source>NUMBER OF COLUMNS</source>
        <translation>ANZAHL SPALTEN</translation>
    </message>
    <message>
        <source>NUMBER OF LINES</source>
        <translation>ANZAHL ZEILEN</translation>
    </message>
    <message>
        <source>PITCH CIRCLE DIAMETR</source>
        <translation>TEILKREIS-DURCHM.</translation>
    </message>
    <message>
        <source>STARTING ANGLE</source>
        <translation>STARTWINKEL</translation>
    </message>
    <message>
        <source>STOPPING ANGLE</source>
        <translation>ENDWINKEL</translation>
    </message>
    <message>
        <source>STEPPING ANGLE</source>
        <translation>WINKELSCHRITT</translation>
    </message>
    <message>
        <source>DEPTH OF COUNTERBORE</source>
        <translation>TIEFE SENKUNG</translation>
    </message>
    <message>
        <source>MATERIAL THICKNESS</source>
        <translation>MATERIALSTÄRKE</translation>
    </message>
    <message>
        <source>OFF-CENTER DISTANCE</source>
        <translation>EXZENTERMASS</translation>
    </message>
    <message>
        <source>TOOL EDGE HEIGHT</source>
        <translation>SCHNEIDENHÖHE</translation>
    </message>
    <message>
        <source>F PRE-POSITIONING</source>
        <translation>VORSCHUB VORPOS.</translation>
    </message>
    <message>
        <source>F COUNTERSINKING</source>
        <translation>VORSCHUB SENKEN</translation>
    </message>
    <message>
        <source>DIST FOR CHIP BRKNG</source>
        <translation>RZ BEI SPANBRUCH</translation>
    </message>
    <message>
        <source>DEPTH FOR CHIP BRKNG</source>
        <translation>TIEFE SPANBRUCH</translation>
    </message>
    <message>
        <source>UPPER ADV STOP DIST</source>
        <translation>OBERER VORHALTEABST.</translation>
    </message>
    <message>
        <source>LOWER ADV STOP DIST</source>
        <translation>UNTERER VORHALTEABST.</translation>
    </message>
    <message>
        <source>MOVE TO CLEARANCE</source>
        <translation>FAHREN AUF S. HÖHE</translation>
    </message>
    <message>
        <source>NOMINAL DIAMETER</source>
        <translation>SOLL-DURCHMESSER</translation>
    </message>
    <message>
        <source>ANGLE OF SPINDLE</source>
        <translation>WINKEL SPINDEL</translation>
    </message>
    <message>
        <source>DATUM NUMBER</source>
        <translation>NULLPUNKT-NUMMER</translation>
    </message>
    <message>
        <source>ROUGHING DIAMETER</source>
        <translation>VORGEB. DURCHMESSER</translation>
    </message>
    <message>
        <source>SELECT DIA./DEPTH</source>
        <translation>AUSWAHL DURCHM./TIEFE</translation>
    </message>
    <message>
        <source>DIAMETER</source>
        <translation>DURCHMESSER</translation>
    </message>
    <message>
        <source>SELECT POS. HEIGHT</source>
        <translation>AUSWAHL POS. HÖHE</translation>
    </message>
    <message>
        <source>CLIMB OR UP-CUT</source>
        <translation>FRÄSART</translation>
    </message>
    <message>
        <source>THREADS PER STEP</source>
        <translation>NACHSETZEN</translation>
    </message>
    <message>
        <source>COUNTERSINKING DEPTH</source>
        <translation>SENKTIEFE</translation>
    </message>
    <message>
        <source>CLEARANCE TO SIDE</source>
        <translation>SICHERH.-ABST. SEITE</translation>
    </message>
    <message>
        <source>DEPTH AT FRONT</source>
        <translation>SENKTIEFE STIRNSEITIG</translation>
    </message>
    <message>
        <source>OFFSET AT FRONT</source>
        <translation>VERSATZ SENKEN STIRN</translation>
    </message>
    <message>
        <source>COUNTERSINK PROCESS</source>
        <translation>SENKVORGANG</translation>
    </message>
    <message>
        <source>TYPE OF TRAVERSE</source>
        <translation>VERFAHRART</translation>
    </message>
    <message>
        <source>TEXT POSITION</source>
        <translation>TEXTLAGE</translation>
    </message>
    <message>
        <source>ALLOWANCE FOR FLOOR</source>
        <translation>AUFMASS TIEFE</translation>
    </message>
    <message>
        <source>MAX. OVERLAP</source>
        <translation>MAX. ÜBERLAPPUNG</translation>
    </message>
    <message>
        <source>STARTING POINT</source>
        <translation>STARTPUNKT</translation>
    </message>
    <message>
        <source>FINISHING FEED RATE</source>
        <translation>VORSCHUB SCHLICHTEN</translation>
    </message>
    <message>
        <source>END POINT 3RD AXIS</source>
        <translation>ENDPUNKT 3. ACHSE</translation>
    </message>
    <message>
        <source>STRATEGY</source>
        <translation>STRATEGIE</translation>
    </message>
    <message>
        <source>DEPTH REFERENCE</source>
        <translation>BEZUG TIEFE</translation>
    </message>
    <message>
        <source>FEED RATE FACTOR</source>
        <translation>VORSCHUBFAKTOR</translation>
    </message>
    <message>
        <source>RPM FACTOR</source>
        <translation>FAKTOR DREHZAHL</translation>
    </message>
    <message>
        <source>DIR. OF SPINDLE ROT.</source>
        <translation>DREHRICHTUNG</translation>
    </message>
    <message>
        <source>ROT.SPEED INFEED/OUT</source>
        <translation>DREHZAHL EIN-/AUSF.</translation>
    </message>
    <message>
        <source>ROT. SPEED DRILLING</source>
        <translation>DREHZAHL BOHREN</translation>
    </message>
    <message>
        <source>COOLANT ON</source>
        <translation>KÜHLUNG EIN</translation>
    </message>
    <message>
        <source>COOLANT OFF</source>
        <translation>KÜHLUNG AUS</translation>
    </message>
    <message>
        <source>DWELL DEPTH</source>
        <translation>VERWEILTIEFE</translation>
    </message>
    <message>
        <source>ENGRAVING TEXT</source>
        <translation>GRAVURTEXT</translation>
    </message>
    <message>
        <source>FEED FOR APPROACH</source>
        <translation>VORSCHUB ANFAHREN</translation>
    </message>
    <message>
        <source>CHARACTER HEIGHT</source>
        <translation>ZEICHENHÖHE</translation>
    </message>
    <message>
        <source>SPACE FACTOR</source>
        <translation>FAKTOR ABSTAND</translation>
    </message>
    <message>
        <source>FONT</source>
        <translation>SCHRIFTART</translation>
    </message>
    <message>
        <source>TEXT LAYOUT</source>
        <translation>TEXTANORDNUNG</translation>
    </message>
    <message>
        <source>CIRCLE RADIUS</source>
        <translation>RADIUS KREIS</translation>
    </message>
    <message>
        <source>MAX. TEXT LENGTH</source>
        <translation>MAX. TEXTLÄNGE</translation>
    </message>
    <message>
        <source>F COUNTERBORING</source>
        <translation>VORSCHUB SENKEN</translation>
    </message>
    <message>
        <source>DEPTH OF THREAD</source>
        <translation>GEWINDETIEFE</translation>
    </message>
    <message>
        <source>MAX. PLUNGING DEPTH</source>
        <translation>MAX. ZUSTELL-TIEFE</translation>
    </message>
    <message>
        <source>TOTAL HOLE DEPTH</source>
        <translation>BOHRTIEFE GESAMT</translation>
    </message>
    <message>
        <source>%1: %2 needs a positive feed after it, e.g. %2 0.1</source>
        <translation>%1: %2 braucht danach einen positiven Vorschub, z. B. %2 0.1</translation>
    </message>
    <message>
        <source>%1: %2 is not allowed here; enter a number</source>
        <translation>%1: %2 ist hier nicht erlaubt; eine Zahl eingeben</translation>
    </message>
    <message>
        <source>%1: %2 is not allowed here; allowed: a number, %3</source>
        <translation>%1: %2 ist hier nicht erlaubt; erlaubt: eine Zahl, %3</translation>
    </message>
    <message>
        <source>%1: enter a value</source>
        <translation>%1: einen Wert eingeben</translation>
    </message>
    <message>
        <source>%1: the text must not contain &quot;</source>
        <translation>%1: der Text darf kein &quot; enthalten</translation>
    </message>
    <message>
        <source>%1: enter axis letters separated by blanks, e.g. X Y</source>
        <translation>%1: Achsbuchstaben durch Leerzeichen getrennt eingeben, z. B. X Y</translation>
    </message>
    <message>
        <source>%1: #n needs a datum number, e.g. #5</source>
        <translation>%1: #n braucht eine Nullpunkt-Nummer, z. B. #5</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: &quot;%2&quot; ist keine Zahl</translation>
    </message>
    <message>
        <source>%1: enter a whole number from %2 to %3</source>
        <translation>%1: eine ganze Zahl von %2 bis %3 eingeben</translation>
    </message>
    <message>
        <source>%1: %2 is outside the range %3 to %4</source>
        <translation>%1: %2 liegt außerhalb des Bereichs %3 bis %4</translation>
    </message>
    <message>
        <source>%1 coordinate of the end point (I before the value: incremental)</source>
        <translation>%1-Koordinate des Endpunkts (I vor dem Wert: inkremental)</translation>
    </message>
    <message>
        <source>Circle radius (negative: arc greater than 180°)</source>
        <translation>Kreisradius (negativ: Bogen größer als 180°)</translation>
    </message>
    <message>
        <source>Chamfer length</source>
        <translation>Fasenlänge</translation>
    </message>
    <message>
        <source>Rounding radius</source>
        <translation>Rundungsradius</translation>
    </message>
    <message>
        <source>Direction of rotation (DR-: clockwise, DR+: counterclockwise)</source>
        <translation>Drehsinn (DR-: im Uhrzeigersinn, DR+: gegen den Uhrzeigersinn)</translation>
    </message>
    <message>
        <source>Radius compensation (RL left, RR right of the contour, R0 none)</source>
        <translation>Radiuskorrektur (RL links, RR rechts der Kontur, R0 keine)</translation>
    </message>
    <message>
        <source>Feed rate (FMAX: rapid traverse, FAUTO: from TOOL CALL)</source>
        <translation>Vorschub (FMAX: Eilgang, FAUTO: aus TOOL CALL)</translation>
    </message>
    <message>
        <source>Miscellaneous functions, e.g. 3 8</source>
        <translation>Zusatzfunktionen, z. B. 3 8</translation>
    </message>
    <message>
        <source>Tool number or name</source>
        <translation>Werkzeugnummer oder -name</translation>
    </message>
    <message>
        <source>Spindle axis</source>
        <translation>Spindelachse</translation>
    </message>
    <message>
        <source>Spindle speed S [1/min]</source>
        <translation>Spindeldrehzahl S [1/min]</translation>
    </message>
    <message>
        <source>Delta length DL</source>
        <translation>Delta-Länge DL</translation>
    </message>
    <message>
        <source>Delta radius DR</source>
        <translation>Delta-Radius DR</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a coordinate</source>
        <translation>%1: &quot;%2&quot; ist keine Koordinate</translation>
    </message>
    <message>
        <source>%1: enter a radius other than 0</source>
        <translation>%1: einen Radius ungleich 0 eingeben</translation>
    </message>
    <message>
        <source>%1: enter a positive number</source>
        <translation>%1: eine positive Zahl eingeben</translation>
    </message>
    <message>
        <source>%1: enter a feed rate, FMAX or FAUTO</source>
        <translation>%1: einen Vorschub, FMAX oder FAUTO eingeben</translation>
    </message>
    <message>
        <source>%1: enter M function numbers, e.g. 3 8</source>
        <translation>%1: Nummern von M-Funktionen eingeben, z. B. 3 8</translation>
    </message>
    <message>
        <source>%1: enter a tool number or a name</source>
        <translation>%1: eine Werkzeugnummer oder einen Namen eingeben</translation>
    </message>
    <message>
        <source>%1: choose one of %2</source>
        <translation>%1: eines von %2 wählen</translation>
    </message>
    <message>
        <source>%1: enter at least one coordinate</source>
        <translation>%1: mindestens eine Koordinate eingeben</translation>
    </message>
    <message>
        <source>Cycle
overview</source>
        <translation>Zyklus-
übersicht</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <source>Edit
cycle</source>
        <translation>Zyklus
editieren</translation>
    </message>
    <message>
        <source>Put the cursor on a CYCL DEF block to edit it.</source>
        <translation>Den Cursor auf einen CYCL DEF-Satz setzen, um ihn zu editieren.</translation>
    </message>
    <message>
        <source>the file is outside the NC root</source>
        <translation>die Datei liegt außerhalb des NC-Stammverzeichnisses</translation>
    </message>
    <message>
        <source>the file does not exist</source>
        <translation>die Datei existiert nicht</translation>
    </message>
    <message>
        <source>the NC root itself cannot be changed</source>
        <translation>das NC-Stammverzeichnis selbst kann nicht geändert werden</translation>
    </message>
    <message>
        <source>the file is protected</source>
        <translation>die Datei ist geschützt</translation>
    </message>
    <message>
        <source>a file with this name exists already</source>
        <translation>eine Datei mit diesem Namen existiert bereits</translation>
    </message>
    <message>
        <source>cannot copy: {1}</source>
        <translation>Kopieren nicht möglich: {1}</translation>
    </message>
    <message>
        <source>cannot move: {1}</source>
        <translation>Verschieben nicht möglich: {1}</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a valid file name</source>
        <translation>&apos;{1}&apos; ist kein gültiger Dateiname</translation>
    </message>
    <message>
        <source>cannot delete: {1}</source>
        <translation>Löschen nicht möglich: {1}</translation>
    </message>
    <message>
        <source>cannot create the folder: {1}</source>
        <translation>Ordner kann nicht angelegt werden: {1}</translation>
    </message>
    <message>
        <source>cannot change the protection: {1}</source>
        <translation>Schutz kann nicht geändert werden: {1}</translation>
    </message>
    <message>
        <source>{1} needs a number, not &quot;{2}&quot;</source>
        <translation>{1} braucht eine Zahl, nicht &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>{1} must be from {2} to {3}</source>
        <translation>{1} muss zwischen {2} und {3} liegen</translation>
    </message>
    <message>
        <source>this table has a fixed row for every entry: edit the values instead</source>
        <translation>diese Tabelle hat für jeden Eintrag eine feste Zeile: stattdessen die Werte ändern</translation>
    </message>
    <message>
        <source>the table is full ({1}{2} to {1}{3})</source>
        <translation>die Tabelle ist voll ({1}{2} bis {1}{3})</translation>
    </message>
    <message>
        <source>the test run stopped after {1} blocks: endless loop?</source>
        <translation>der Programm-Test hat nach {1} Sätzen angehalten: Endlosschleife?</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a regular file</source>
        <translation>&apos;{1}&apos; ist keine reguläre Datei</translation>
    </message>
    <message>
        <source>cannot write program {1}: {2}</source>
        <translation>Programm {1} kann nicht geschrieben werden: {2}</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is a link: Kerf does not write through links</source>
        <translation>&apos;{1}&apos; ist ein Link: Kerf schreibt nicht über Links</translation>
    </message>
    <message>
        <source>and {1} more diagnostics</source>
        <translation>und {1} weitere Meldungen</translation>
    </message>
    <message>
        <source>overflow: the result of &apos;{1}&apos; is too large</source>
        <translation>Überlauf: das Ergebnis von &apos;{1}&apos; ist zu groß</translation>
    </message>
    <message>
        <source>an expression may nest at most {1} levels</source>
        <translation>ein Ausdruck darf höchstens {1} Ebenen tief verschachtelt sein</translation>
    </message>
    <message>
        <source>P{1}: the value is too large (overflow)</source>
        <translation>P{1}: der Wert ist zu groß (Überlauf)</translation>
    </message>
    <message>
        <source>{1}{2} holds no finite number</source>
        <translation>{1}{2} enthält keine endliche Zahl</translation>
    </message>
    <message>
        <source>a formula may nest at most {1} levels</source>
        <translation>eine Formel darf höchstens {1} Ebenen tief verschachtelt sein</translation>
    </message>
    <message>
        <source>a string may hold at most {1} characters, not {2}</source>
        <translation>eine Zeichenkette darf höchstens {1} Zeichen enthalten, nicht {2}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the range of the control (at most {3})</source>
        <translation>{1} = {2} liegt außerhalb des Bereichs der Steuerung (höchstens {3})</translation>
    </message>
    <message>
        <source>Programs and MDI run only after the axes are homed (Home all); false lets a machine without reference switches run from power-on</source>
        <translation>Programme und MDI laufen erst nach dem Referenzieren der Achsen (Alle referenzieren); false lässt eine Maschine ohne Referenzschalter ab dem Einschalten laufen</translation>
    </message>
    <message>
        <source>Order of the axis in Home all: lower numbers are homed first</source>
        <translation>Reihenfolge der Achse bei Alle referenzieren: kleinere Nummern zuerst</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; changed while it was opened: a link appeared</source>
        <translation>&apos;{1}&apos; hat sich beim Öffnen geändert: ein Link ist aufgetaucht</translation>
    </message>
    <message>
        <source>{1} must be 0, 1 or 2 for tapping</source>
        <translation>{1} muss beim Gewindebohren 0, 1 oder 2 sein</translation>
    </message>
    <message>
        <source>rigid tapping needs a feed and a spindle speed</source>
        <translation>Gewindebohren ohne Ausgleichsfutter braucht einen Vorschub und eine Spindeldrehzahl</translation>
    </message>
    <message>
        <source>the pecks shrink below 0.001 mm before the depth I: program L</source>
        <translation>die Zustellungen werden vor der Tiefe I kleiner als 0,001 mm: L programmieren</translation>
    </message>
    <message>
        <source>the groove has no depth</source>
        <translation>der Einstich hat keine Tiefe</translation>
    </message>
    <message>
        <source>the groove is narrower than the tool&apos;s cutting width NOSEW</source>
        <translation>der Einstich ist schmaler als die Schneidenbreite NOSEW des Werkzeugs</translation>
    </message>
    <message>
        <source>C is not programmed and the tool has no cutting width NOSEW</source>
        <translation>C ist nicht programmiert und das Werkzeug hat keine Schneidenbreite NOSEW</translation>
    </message>
    <message>
        <source>the tool position is not correct for the cycle ({1})</source>
        <translation>die Werkzeugposition ist für den Zyklus nicht richtig ({1})</translation>
    </message>
    <message>
        <source>the cycle would need more than {1} moves: {2} is too small</source>
        <translation>der Zyklus bräuchte mehr als {1} Bewegungen: {2} ist zu klein</translation>
    </message>
    <message>
        <source>the section has no length along the passes</source>
        <translation>der Abschnitt hat keine Länge in Richtung der Schnitte</translation>
    </message>
    <message>
        <source>the thread has no length along its axis</source>
        <translation>das Gewinde hat keine Länge entlang seiner Achse</translation>
    </message>
    <message>
        <source>{1} leaves no thread to cut between the start and the end</source>
        <translation>{1} lässt zwischen Anfang und Ende kein Gewinde zum Schneiden übrig</translation>
    </message>
    <message>
        <source>{1} is not a parameter of {2}</source>
        <translation>{1} ist kein Parameter von {2}</translation>
    </message>
    <message>
        <source>{1} of {2} needs a value</source>
        <translation>{1} von {2} braucht einen Wert</translation>
    </message>
    <message>
        <source>{1} of {2} cannot be 0</source>
        <translation>{1} von {2} darf nicht 0 sein</translation>
    </message>
    <message>
        <source>{1} needs its parameter {2}</source>
        <translation>{1} braucht seinen Parameter {2}</translation>
    </message>
    <message>
        <source>{1}: M (pitch change) cannot be programmed with K (repass)</source>
        <translation>{1}: M (Steigungsänderung) kann nicht mit K (Nachschneiden) programmiert werden</translation>
    </message>
    <message>
        <source>{1} and {2}: one canned cycle per block</source>
        <translation>{1} und {2}: ein Festzyklus pro Satz</translation>
    </message>
    <message>
        <source>the start and the end of an arc are not on one circle about its centre</source>
        <translation>Anfang und Ende eines Bogens liegen nicht auf einem Kreis um seinen Mittelpunkt</translation>
    </message>
    <message>
        <source>an arc of the profile must stay within a quarter circle</source>
        <translation>ein Bogen des Profils darf höchstens einen Viertelkreis umfassen</translation>
    </message>
    <message>
        <source>label N{1} of the profile is not in the program</source>
        <translation>die Satznummer N{1} des Profils ist nicht im Programm</translation>
    </message>
    <message>
        <source>the profile ends (E) before it starts (S)</source>
        <translation>das Profil endet (E) vor seinem Anfang (S)</translation>
    </message>
    <message>
        <source>a profile holds no high-level blocks</source>
        <translation>ein Profil enthält keine Sätze in Hochsprache</translation>
    </message>
    <message>
        <source>{1} is not allowed in a profile</source>
        <translation>{1} ist in einem Profil nicht erlaubt</translation>
    </message>
    <message>
        <source>the profile has more than 10000 elements</source>
        <translation>das Profil hat mehr als 10000 Elemente</translation>
    </message>
    <message>
        <source>this machine has no axis {1}</source>
        <translation>diese Maschine hat keine Achse {1}</translation>
    </message>
    <message>
        <source>MACHINING OPERATION</source>
        <translation>BEARBEITUNGS-UMFANG</translation>
    </message>
    <message>
        <source>CORNER RADIUS</source>
        <translation>ECKENRADIUS</translation>
    </message>
    <message>
        <source>WORKPIECE BLANK DIA.</source>
        <translation>ROHTEIL-DURCHMESSER</translation>
    </message>
    <message>
        <source>CIRCLE DIAMETER</source>
        <translation>KREISDURCHMESSER</translation>
    </message>
    <message>
        <source>ANGULAR LENGTH</source>
        <translation>WINKELLAENGE</translation>
    </message>
    <message>
        <source>INFEED FOR FINISHING</source>
        <translation>ZUSTELLUNG SCHLICHTEN</translation>
    </message>
    <message>
        <source>PLUNGE</source>
        <translation>EINTAUCHEN</translation>
    </message>
    <message>
        <source>ALLOWANCE FOR SIDE</source>
        <translation>AUFMASS SEITE</translation>
    </message>
    <message>
        <source>WORKPC. BLANK SIDE 1</source>
        <translation>ROHTEILMASS 1</translation>
    </message>
    <message>
        <source>WORKPC. BLANK SIDE 2</source>
        <translation>ROHTEILMASS 2</translation>
    </message>
    <message>
        <source>APPROACH POSITION</source>
        <translation>ANFAHRPOSITION</translation>
    </message>
    <message>
        <source>FEED RATE REFERENCE</source>
        <translation>BEZUG VORSCHUB</translation>
    </message>
    <message>
        <source>REF-CIRCLE DIAMETER</source>
        <translation>DURCHMESSER BEZUGSKR.</translation>
    </message>
    <message>
        <source>NUMBER OF CORNERS</source>
        <translation>ECKENANZAHL</translation>
    </message>
    <message>
        <source>REFERENCE CIRCLE</source>
        <translation>BEZUGSKREIS</translation>
    </message>
    <message>
        <source>POCKET POSITION</source>
        <translation>TASCHENLAGE</translation>
    </message>
    <message>
        <source>SLOT LENGTH</source>
        <translation>NUTLAENGE</translation>
    </message>
    <message>
        <source>SLOT WIDTH</source>
        <translation>NUTBREITE</translation>
    </message>
    <message>
        <source>SLOT POSITION</source>
        <translation>NUTLAGE</translation>
    </message>
    <message>
        <source>REF. SLOT POSITION</source>
        <translation>BEZUG NUTLAGE</translation>
    </message>
    <message>
        <source>RADIUS / CHAMFER</source>
        <translation>RADIUS / FASE</translation>
    </message>
    <message>
        <source>STUD POSITION</source>
        <translation>ZAPFENLAGE</translation>
    </message>
    <message>
        <source>FINISHED PART DIA.</source>
        <translation>FERTIGTEIL-DURCHM.</translation>
    </message>
    <message>
        <source>Corner radius (0: tool radius)</source>
        <translation>Eckenradius (0: Werkzeugradius)</translation>
    </message>
    <message>
        <source>RECTANGULAR POCKET</source>
        <translation>RECHTECKTASCHE</translation>
    </message>
    <message>
        <source>Circle diameter</source>
        <translation>Kreisdurchmesser</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 helical)</source>
        <translation>Eintauchstrategie (0 senkrecht, 1 helixförmig)</translation>
    </message>
    <message>
        <source>cycle {1}: vertical plunging (Q366 = 0) needs a tool whose ANGLE is 0 or 90</source>
        <translation>Zyklus {1}: senkrechtes Eintauchen (Q366 = 0) braucht ein Werkzeug mit ANGLE 0 oder 90</translation>
    </message>
    <message>
        <source>CIRCULAR POCKET</source>
        <translation>KREISTASCHE</translation>
    </message>
    <message>
        <source>Slot length</source>
        <translation>Nutlänge</translation>
    </message>
    <message>
        <source>Slot width</source>
        <translation>Nutbreite</translation>
    </message>
    <message>
        <source>Slot position (0 centre, 1 left end, 2 centre of the left arc, 3 centre of the right arc, 4 right end)</source>
        <translation>Lage der Nut (0 Mitte, 1 linkes Ende, 2 Mitte linker Kreisbogen, 3 Mitte rechter Kreisbogen, 4 rechtes Ende)</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width Q219 is larger than its length Q218</source>
        <translation>Zyklus {1}: die Nutbreite Q219 ist größer als die Nutlänge Q218</translation>
    </message>
    <message>
        <source>SLOT MILLING</source>
        <translation>NUTENFRÄSEN</translation>
    </message>
    <message>
        <source>Reference of the slot position (0 centre Q216/Q217, 1 start arc, 2 middle, 3 end arc at the tool position)</source>
        <translation>Bezug der Nutlage (0 Mitte Q216/Q217, 1 Anfangsbogen, 2 Mitte, 3 Endbogen an der Werkzeugposition)</translation>
    </message>
    <message>
        <source>Angular length of the slot</source>
        <translation>Winkellänge der Nut</translation>
    </message>
    <message>
        <source>Stepping angle between repetitions</source>
        <translation>Winkelschritt zwischen den Wiederholungen</translation>
    </message>
    <message>
        <source>Number of repetitions</source>
        <translation>Anzahl der Wiederholungen</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width Q219 must be smaller than the pitch circle diameter Q375</source>
        <translation>Zyklus {1}: die Nutbreite Q219 muss kleiner als der Teilkreisdurchmesser Q375 sein</translation>
    </message>
    <message>
        <source>cycle {1}: the angular length Q248 closes the slot on itself</source>
        <translation>Zyklus {1}: die Winkellänge Q248 schließt die Nut in sich</translation>
    </message>
    <message>
        <source>CIRCULAR SLOT</source>
        <translation>KREISNUT</translation>
    </message>
    <message>
        <source>Workpiece blank side length 1</source>
        <translation>Rohteilmaß Seitenlänge 1</translation>
    </message>
    <message>
        <source>Workpiece blank side length 2</source>
        <translation>Rohteilmaß Seitenlänge 2</translation>
    </message>
    <message>
        <source>Corner radius (+) or chamfer (-)</source>
        <translation>Eckenradius (+) oder Fase (-)</translation>
    </message>
    <message>
        <source>Approach position (0 right of the stud, 1-4 corners)</source>
        <translation>Anfahrposition (0 rechts vom Zapfen, 1-4 Ecken)</translation>
    </message>
    <message>
        <source>cycle {1}: the workpiece blank is smaller than the finished part</source>
        <translation>Zyklus {1}: das Rohteil ist kleiner als das Fertigteil</translation>
    </message>
    <message>
        <source>RECTANGULAR STUD</source>
        <translation>RECHTECKZAPFEN</translation>
    </message>
    <message>
        <source>Finished part diameter</source>
        <translation>Fertigteil-Durchmesser</translation>
    </message>
    <message>
        <source>Workpiece blank diameter</source>
        <translation>Rohteil-Durchmesser</translation>
    </message>
    <message>
        <source>CIRCULAR STUD</source>
        <translation>KREISZAPFEN</translation>
    </message>
    <message>
        <source>Reference circle (0 inscribed, 1 circumscribed)</source>
        <translation>Bezugskreis (0 Innenkreis, 1 Umkreis)</translation>
    </message>
    <message>
        <source>Reference circle diameter</source>
        <translation>Durchmesser des Bezugskreises</translation>
    </message>
    <message>
        <source>Number of corners</source>
        <translation>Anzahl der Ecken</translation>
    </message>
    <message>
        <source>Angle of the first corner</source>
        <translation>Winkel der ersten Ecke</translation>
    </message>
    <message>
        <source>cycle {1}: a polygon needs at least 3 corners (Q572)</source>
        <translation>Zyklus {1}: ein Polygon braucht mindestens 3 Ecken (Q572)</translation>
    </message>
    <message>
        <source>cycle {1}: the corner radius or chamfer Q220 is too large for the sides of the polygon</source>
        <translation>Zyklus {1}: Eckenradius oder Fase Q220 ist zu groß für die Seiten des Polygons</translation>
    </message>
    <message>
        <source>POLYGON STUD</source>
        <translation>POLYGONZAPFEN</translation>
    </message>
    <message>
        <source>cycle {1} needs a tool with a radius greater than 0</source>
        <translation>Zyklus {1} braucht ein Werkzeug mit einem Radius größer als 0</translation>
    </message>
    <message>
        <source>cycle {1}: helical or reciprocating plunging (Q366) needs the plunge angle ANGLE of the tool</source>
        <translation>Zyklus {1}: helixförmiges oder pendelndes Eintauchen (Q366) braucht den Eintauchwinkel ANGLE des Werkzeugs</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is too large for the programmed size and finishing allowance</source>
        <translation>Zyklus {1}: das Werkzeug ist zu groß für das programmierte Maß und Schlichtaufmaß</translation>
    </message>
    <message>
        <source>cycle {1}: no room for the helical plunge: the helix needs a diameter of twice the tool diameter</source>
        <translation>Zyklus {1}: kein Platz zum helixförmigen Eintauchen: die Helix braucht den doppelten Werkzeugdurchmesser</translation>
    </message>
    <message>
        <source>cycle {1}: no room for reciprocating plunging: it needs a length of twice the tool diameter</source>
        <translation>Zyklus {1}: kein Platz zum pendelnden Eintauchen: es braucht die Länge des doppelten Werkzeugdurchmessers</translation>
    </message>
    <message>
        <source>Machining operation (0 roughing and finishing, 1 roughing, 2 finishing)</source>
        <translation>Bearbeitungsumfang (0 Schruppen und Schlichten, 1 Schruppen, 2 Schlichten)</translation>
    </message>
    <message>
        <source>First side length</source>
        <translation>1. Seitenlänge</translation>
    </message>
    <message>
        <source>Second side length</source>
        <translation>2. Seitenlänge</translation>
    </message>
    <message>
        <source>Finishing allowance for the side</source>
        <translation>Schlichtaufmaß Seite</translation>
    </message>
    <message>
        <source>Position (0 centre, 1 lower left, 2 lower right, 3 upper right, 4 upper left corner)</source>
        <translation>Lage (0 Mitte, 1 Ecke links unten, 2 rechts unten, 3 rechts oben, 4 links oben)</translation>
    </message>
    <message>
        <source>Infeed for finishing (0: one infeed)</source>
        <translation>Zustellung Schlichten (0: eine Zustellung)</translation>
    </message>
    <message>
        <source>Feed rate reference (0 tool centre, 1 cutting edge when side finishing, 2 also floor finishing, 3 always)</source>
        <translation>Bezug Vorschub (0 Werkzeugmitte, 1 Schneide beim Schlichten der Seite, 2 auch beim Schlichten des Bodens, 3 immer)</translation>
    </message>
    <message>
        <source>Code number asked before machine parameters may be edited</source>
        <translation>Schlüsselzahl, die vor dem Bearbeiten der Maschinenparameter abgefragt wird</translation>
    </message>
    <message>
        <source>the profile has no length</source>
        <translation>das Profil hat keine Länge</translation>
    </message>
    <message>
        <source>the profile cannot be copied at the distance of a pass: it is too narrow</source>
        <translation>das Profil lässt sich nicht im Abstand eines Durchgangs kopieren: es ist zu schmal</translation>
    </message>
    <message>
        <source>the profile runs back against the passes (an undercut): the tool cannot reach it</source>
        <translation>das Profil läuft entgegen den Durchgängen zurück (Hinterschnitt): das Werkzeug erreicht es nicht</translation>
    </message>
    <message>
        <source>the section runs back under the material</source>
        <translation>der Abschnitt läuft unter das Material zurück</translation>
    </message>
    <message>
        <source>{1} cannot make an arc to this end point</source>
        <translation>{1} kann keinen Bogen zu diesem Endpunkt bilden</translation>
    </message>
    <message>
        <source>a profile has one raw-stock part (one G00)</source>
        <translation>ein Profil hat ein einziges Rohteilprofil (ein G00)</translation>
    </message>
    <message>
        <source>the G00 block starts the raw-stock profile: it needs its point</source>
        <translation>der G00-Satz beginnt das Rohteilprofil: er braucht seinen Punkt</translation>
    </message>
    <message>
        <source>cycle parameters belong to a cycle block (G2xx, G4xx ...)</source>
        <translation>Zyklusparameter gehören in einen Zyklus-Satz (G2xx, G4xx ...)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not allowed in this block</source>
        <translation>&apos;{1}&apos; ist in diesem Satz nicht erlaubt</translation>
    </message>
    <message>
        <source>program name expected after &apos;%&apos;</source>
        <translation>Programmname nach &apos;%&apos; erwartet</translation>
    </message>
    <message>
        <source>P0{1} expected</source>
        <translation>P0{1} erwartet</translation>
    </message>
    <message>
        <source>label number expected</source>
        <translation>Label-Nummer erwartet</translation>
    </message>
    <message>
        <source>two path functions in one block</source>
        <translation>zwei Bahnfunktionen in einem Satz</translation>
    </message>
    <message>
        <source>G70/G71 belong to the program header &apos;%NAME&apos;</source>
        <translation>G70/G71 gehören in den Programmkopf &apos;%NAME&apos;</translation>
    </message>
    <message>
        <source>G{1} and G{2} cannot share a block</source>
        <translation>G{1} und G{2} können nicht im selben Satz stehen</translation>
    </message>
    <message>
        <source>value expected after &apos;{1}&apos;</source>
        <translation>Wert nach &apos;{1}&apos; erwartet</translation>
    </message>
    <message>
        <source>a label has no repeat count</source>
        <translation>ein Label hat keine Wiederholungszahl</translation>
    </message>
    <message>
        <source>label number expected (G98 L1)</source>
        <translation>Label-Nummer erwartet (G98 L1)</translation>
    </message>
    <message>
        <source>tool number expected (T)</source>
        <translation>Werkzeugnummer erwartet (T)</translation>
    </message>
    <message>
        <source>the plane belongs to G30</source>
        <translation>die Ebene gehört zu G30</translation>
    </message>
    <message>
        <source>R expected after G{1}</source>
        <translation>R nach G{1} erwartet</translation>
    </message>
    <message>
        <source>unknown G function G{1}</source>
        <translation>unbekannte G-Funktion G{1}</translation>
    </message>
    <message>
        <source>G17/G18/G19 belong to a tool call (T) or a blank (G30)</source>
        <translation>G17/G18/G19 gehören zu einem Werkzeug-Aufruf (T) oder einem Rohteil (G30)</translation>
    </message>
    <message>
        <source>no path function (G00, G01, G02 ...) is active</source>
        <translation>keine Bahnfunktion (G00, G01, G02 ...) aktiv</translation>
    </message>
    <message>
        <source>a feed rate F is not allowed with rapid G{1}</source>
        <translation>ein Vorschub F ist im Eilgang G{1} nicht erlaubt</translation>
    </message>
    <message>
        <source>{1} expected after G{2}</source>
        <translation>{1} nach G{2} erwartet</translation>
    </message>
    <message>
        <source>program name expected (P01 &quot;NAME&quot;)</source>
        <translation>Programmname erwartet (P01 &quot;NAME&quot;)</translation>
    </message>
    <message>
        <source>contour labels expected (P01 1)</source>
        <translation>Kontur-Labels erwartet (P01 1)</translation>
    </message>
    <message>
        <source>text after the block end &apos;*&apos;</source>
        <translation>Text nach dem Satzende &apos;*&apos;</translation>
    </message>
    <message>
        <source>closing &apos;&quot;&apos; missing</source>
        <translation>schließendes &apos;&quot;&apos; fehlt</translation>
    </message>
    <message>
        <source>number expected after &apos;{1}&apos;</source>
        <translation>Zahl nach &apos;{1}&apos; erwartet</translation>
    </message>
    <message>
        <source>repeat count expected after &apos;,&apos;</source>
        <translation>Wiederholungszahl nach &apos;,&apos; erwartet</translation>
    </message>
    <message>
        <source>cycle {1}: the stepping angle Q247 must be at least 5 degrees</source>
        <translation>Zyklus {1}: der Winkelschritt Q247 muss mindestens 5 Grad betragen</translation>
    </message>
    <message>
        <source>cycle {1}: the touch points give no circle</source>
        <translation>Zyklus {1}: die Antastpunkte ergeben keinen Kreis</translation>
    </message>
    <message>
        <source>1st touch point, main axis</source>
        <translation>1. Antastpunkt Hauptachse</translation>
    </message>
    <message>
        <source>1st touch point, secondary axis</source>
        <translation>1. Antastpunkt Nebenachse</translation>
    </message>
    <message>
        <source>Spacing of touch points 1 and 2 in the main axis</source>
        <translation>Abstand der Antastpunkte 1 und 2 in der Hauptachse</translation>
    </message>
    <message>
        <source>3rd touch point, main axis</source>
        <translation>3. Antastpunkt Hauptachse</translation>
    </message>
    <message>
        <source>3rd touch point, secondary axis</source>
        <translation>3. Antastpunkt Nebenachse</translation>
    </message>
    <message>
        <source>Spacing of touch points 3 and 4 in the secondary axis</source>
        <translation>Abstand der Antastpunkte 3 und 4 in der Nebenachse</translation>
    </message>
    <message>
        <source>Basic rotation too: 0 no, 1 yes</source>
        <translation>Auch Grunddrehung setzen: 0 nein, 1 ja</translation>
    </message>
    <message>
        <source>Corner, main axis</source>
        <translation>Ecke Hauptachse</translation>
    </message>
    <message>
        <source>Corner, secondary axis</source>
        <translation>Ecke Nebenachse</translation>
    </message>
    <message>
        <source>Corner: 1 (-M -S), 2 (+M -S), 3 (+M +S), 4 (-M +S)</source>
        <translation>Ecke: 1 (-M -S), 2 (+M -S), 3 (+M +S), 4 (-M +S)</translation>
    </message>
    <message>
        <source>Bolt-circle centre, main axis</source>
        <translation>Lochkreis-Mitte Hauptachse</translation>
    </message>
    <message>
        <source>Bolt-circle centre, secondary axis</source>
        <translation>Lochkreis-Mitte Nebenachse</translation>
    </message>
    <message>
        <source>Nominal bolt-circle diameter</source>
        <translation>Soll-Durchmesser des Lochkreises</translation>
    </message>
    <message>
        <source>Polar angle of the 1st hole centre</source>
        <translation>Polarwinkel der 1. Bohrungsmitte</translation>
    </message>
    <message>
        <source>Polar angle of the 2nd hole centre</source>
        <translation>Polarwinkel der 2. Bohrungsmitte</translation>
    </message>
    <message>
        <source>Polar angle of the 3rd hole centre</source>
        <translation>Polarwinkel der 3. Bohrungsmitte</translation>
    </message>
    <message>
        <source>cycle {1}: the two edges are parallel</source>
        <translation>Zyklus {1}: die beiden Kanten sind parallel</translation>
    </message>
    <message>
        <source>cycle {1}: the hole centres give no circle</source>
        <translation>Zyklus {1}: die Bohrungsmitten ergeben keinen Kreis</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE CORNER</source>
        <translation>BEZUGSPUNKT ECKE AUSSEN</translation>
    </message>
    <message>
        <source>DATUM INSIDE CORNER</source>
        <translation>BEZUGSPUNKT ECKE INNEN</translation>
    </message>
    <message>
        <source>DATUM CIRCLE CENTER</source>
        <translation>BEZUGSPUNKT LOCHKREIS-MITTE</translation>
    </message>
    <message>
        <source>Nominal intersection, main axis</source>
        <translation>Soll-Schnittpunkt Hauptachse</translation>
    </message>
    <message>
        <source>Nominal intersection, secondary axis</source>
        <translation>Soll-Schnittpunkt Nebenachse</translation>
    </message>
    <message>
        <source>Nominal position in the tool axis: the measuring height</source>
        <translation>Soll-Position in der Werkzeugachse: die Messhöhe</translation>
    </message>
    <message>
        <source>Tolerance of the 1st edge along its normal, e.g. &quot;0.1-0.1&quot;</source>
        <translation>Toleranz der 1. Kante entlang ihrer Normalen, z. B. &quot;0.1-0.1&quot;</translation>
    </message>
    <message>
        <source>Nominal angle of the 1st line</source>
        <translation>Soll-Winkel der 1. Geraden</translation>
    </message>
    <message>
        <source>Probing direction of the 1st line: +1 angle + 90, -1 - 90</source>
        <translation>Antastrichtung der 1. Geraden: +1 Winkel + 90, -1 - 90</translation>
    </message>
    <message>
        <source>Intersection to the 1st touch point of the 1st line</source>
        <translation>Abstand vom Schnittpunkt zum 1. Antastpunkt der 1. Geraden</translation>
    </message>
    <message>
        <source>Intersection to the 2nd touch point of the 1st line</source>
        <translation>Abstand vom Schnittpunkt zum 2. Antastpunkt der 1. Geraden</translation>
    </message>
    <message>
        <source>Tolerance of the 2nd edge along its normal</source>
        <translation>Toleranz der 2. Kante entlang ihrer Normalen</translation>
    </message>
    <message>
        <source>Nominal angle of the 2nd line</source>
        <translation>Soll-Winkel der 2. Geraden</translation>
    </message>
    <message>
        <source>Probing direction of the 2nd line: +1 angle + 90, -1 - 90</source>
        <translation>Antastrichtung der 2. Geraden: +1 Winkel + 90, -1 - 90</translation>
    </message>
    <message>
        <source>Intersection to the 1st touch point of the 2nd line</source>
        <translation>Abstand vom Schnittpunkt zum 1. Antastpunkt der 2. Geraden</translation>
    </message>
    <message>
        <source>Intersection to the 2nd touch point of the 2nd line</source>
        <translation>Abstand vom Schnittpunkt zum 2. Antastpunkt der 2. Geraden</translation>
    </message>
    <message>
        <source>Plane of the angles: 1 YZ, 2 ZX, 3 XY</source>
        <translation>Ebene der Winkel: 1 YZ, 2 ZX, 3 XY</translation>
    </message>
    <message>
        <source>Clearance height: -1 never, 0 cycle, 1 each edge, 2 each touch point</source>
        <translation>Sichere Höhe: -1 nie, 0 Zyklus, 1 jede Kante, 2 jeder Antastpunkt</translation>
    </message>
    <message>
        <source>Tolerance error: 0 nothing, 1 stop, 2 stop on scrap only</source>
        <translation>Toleranzfehler: 0 nichts, 1 Halt, 2 Halt nur bei Ausschuss</translation>
    </message>
    <message>
        <source>Align rotary axes: 0 no, 1 MOVE, 2 TURN</source>
        <translation>Drehachsen ausrichten: 0 nein, 1 MOVE, 2 TURN</translation>
    </message>
    <message>
        <source>Transfer position into the active preset: 0 no, 1 yes</source>
        <translation>Position in den aktiven Bezugspunkt übernehmen: 0 nein, 1 ja</translation>
    </message>
    <message>
        <source>Accept rotation: 0 no, 1/3/5 basic rotation from edge 1/2/mean</source>
        <translation>Drehung übernehmen: 0 nein, 1/3/5 Grunddrehung aus Kante 1/2/Mittelwert</translation>
    </message>
    <message>
        <source>cycle {1}: aligning the rotary axes (Q1126) needs the rotation accepted (Q1121)</source>
        <translation>Zyklus {1}: das Ausrichten der Drehachsen (Q1126) setzt die Übernahme der Drehung (Q1121) voraus</translation>
    </message>
    <message>
        <source>cycle {1}: this machine has no rotary table axis to correct the rotation with</source>
        <translation>Zyklus {1}: diese Maschine hat keine Rundtischachse, mit der die Drehung korrigiert werden kann</translation>
    </message>
    <message>
        <source>cycle {1}: tolerance QS{2} = &quot;{3}&quot; is not &quot;upper-lower&quot; or a number</source>
        <translation>Zyklus {1}: Toleranz QS{2} = &quot;{3}&quot; ist weder &quot;oben-unten&quot; noch eine Zahl</translation>
    </message>
    <message>
        <source>cycle {1}: tolerance exceeded ({2})</source>
        <translation>Zyklus {1}: Toleranz überschritten ({2})</translation>
    </message>
    <message>
        <source>PROBING INTERSECTION</source>
        <translation>ANTASTEN SCHNITTPUNKT</translation>
    </message>
    <message>
        <source>2nd touch point, main axis</source>
        <translation>2. Antastpunkt Hauptachse</translation>
    </message>
    <message>
        <source>2nd touch point, secondary axis</source>
        <translation>2. Antastpunkt Nebenachse</translation>
    </message>
    <message>
        <source>Preset rotation angle: angle of the reference line</source>
        <translation>Voreinstellung Drehwinkel: Winkel der Bezugsgeraden</translation>
    </message>
    <message>
        <source>BASIC ROTATION</source>
        <translation>GRUNDDREHUNG</translation>
    </message>
    <message>
        <source>Centre in the main axis</source>
        <translation>Mitte in der Hauptachse</translation>
    </message>
    <message>
        <source>Centre in the secondary axis</source>
        <translation>Mitte in der Nebenachse</translation>
    </message>
    <message>
        <source>Side length parallel to the main axis</source>
        <translation>Seitenlänge parallel zur Hauptachse</translation>
    </message>
    <message>
        <source>Side length parallel to the secondary axis</source>
        <translation>Seitenlänge parallel zur Nebenachse</translation>
    </message>
    <message>
        <source>Touch point, main axis</source>
        <translation>Antastpunkt Hauptachse</translation>
    </message>
    <message>
        <source>Touch point, secondary axis</source>
        <translation>Antastpunkt Nebenachse</translation>
    </message>
    <message>
        <source>Touch point, nominal surface in the tool axis</source>
        <translation>Antastpunkt: Soll-Oberfläche in der Werkzeugachse</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main, 2 secondary, 3 tool axis</source>
        <translation>Messachse: 1 Hauptachse, 2 Nebenachse, 3 Werkzeugachse</translation>
    </message>
    <message>
        <source>New datum in the measuring axis</source>
        <translation>Neuer Bezugspunkt in der Messachse</translation>
    </message>
    <message>
        <source>DATUM INSIDE RECTANGLE</source>
        <translation>BEZUGSPUNKT RECHTECK INNEN</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE RECTANGLE</source>
        <translation>BEZUGSPUNKT RECHTECK AUSSEN</translation>
    </message>
    <message>
        <source>DATUM INSIDE CIRCLE</source>
        <translation>BEZUGSPUNKT KREIS INNEN</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE CIRCLE</source>
        <translation>BEZUGSPUNKT KREIS AUSSEN</translation>
    </message>
    <message>
        <source>DATUM IN TS AXIS</source>
        <translation>BEZUGSPUNKT TS-ACHSE</translation>
    </message>
    <message>
        <source>DATUM IN ONE AXIS</source>
        <translation>BEZUGSPUNKT EINZELNE ACHSE</translation>
    </message>
    <message>
        <source>cycle {1}: define the measured-value transfer (Q303)</source>
        <translation>Zyklus {1}: die Messwert-Übergabe (Q303) definieren</translation>
    </message>
    <message>
        <source>Nominal centre, main axis</source>
        <translation>Soll-Mitte Hauptachse</translation>
    </message>
    <message>
        <source>Nominal centre, secondary axis</source>
        <translation>Soll-Mitte Nebenachse</translation>
    </message>
    <message>
        <source>Maximum permitted diameter (0: not monitored)</source>
        <translation>Größter zulässiger Durchmesser (0: nicht überwacht)</translation>
    </message>
    <message>
        <source>Minimum permitted diameter</source>
        <translation>Kleinster zulässiger Durchmesser</translation>
    </message>
    <message>
        <source>Centre tolerance, main axis (0: not monitored)</source>
        <translation>Mittentoleranz Hauptachse (0: nicht überwacht)</translation>
    </message>
    <message>
        <source>Centre tolerance, secondary axis</source>
        <translation>Mittentoleranz Nebenachse</translation>
    </message>
    <message>
        <source>Compatibility only, no effect</source>
        <translation>Nur zur Kompatibilität, ohne Wirkung</translation>
    </message>
    <message>
        <source>Starting point, main axis</source>
        <translation>Startpunkt Hauptachse</translation>
    </message>
    <message>
        <source>Starting point, secondary axis</source>
        <translation>Startpunkt Nebenachse</translation>
    </message>
    <message>
        <source>Offset before the second measurement (0: none)</source>
        <translation>Versatz vor der zweiten Messung (0: keiner)</translation>
    </message>
    <message>
        <source>Nominal length</source>
        <translation>Soll-Länge</translation>
    </message>
    <message>
        <source>Maximum permitted length (0: not monitored)</source>
        <translation>Größte zulässige Länge (0: nicht überwacht)</translation>
    </message>
    <message>
        <source>Minimum permitted length</source>
        <translation>Kleinste zulässige Länge</translation>
    </message>
    <message>
        <source>Nominal side length parallel to the main axis</source>
        <translation>Soll-Seitenlänge parallel zur Hauptachse</translation>
    </message>
    <message>
        <source>Nominal side length parallel to the secondary axis</source>
        <translation>Soll-Seitenlänge parallel zur Nebenachse</translation>
    </message>
    <message>
        <source>Maximum length of side 1 (0: not monitored)</source>
        <translation>Größte Länge der Seite 1 (0: nicht überwacht)</translation>
    </message>
    <message>
        <source>Minimum length of side 1</source>
        <translation>Kleinste Länge der Seite 1</translation>
    </message>
    <message>
        <source>Maximum length of side 2 (0: not monitored)</source>
        <translation>Größte Länge der Seite 2 (0: nicht überwacht)</translation>
    </message>
    <message>
        <source>Minimum length of side 2</source>
        <translation>Kleinste Länge der Seite 2</translation>
    </message>
    <message>
        <source>Maximum permitted value (0 with Q289 = 0: not monitored)</source>
        <translation>Größter zulässiger Wert (0 bei Q289 = 0: nicht überwacht)</translation>
    </message>
    <message>
        <source>Minimum permitted value</source>
        <translation>Kleinster zulässiger Wert</translation>
    </message>
    <message>
        <source>MEASURE ANGLE</source>
        <translation>MESSEN WINKEL</translation>
    </message>
    <message>
        <source>MEASURE RECTANGLE INSIDE</source>
        <translation>MESSEN RECHTECK INNEN</translation>
    </message>
    <message>
        <source>MEASURE RECTANGLE OUTSIDE</source>
        <translation>MESSEN RECHTECK AUSSEN</translation>
    </message>
    <message>
        <source>MEASURE COORDINATE</source>
        <translation>MESSEN KOORDINATE</translation>
    </message>
    <message>
        <source>MEASURE HOLE</source>
        <translation>MESSEN BOHRUNG</translation>
    </message>
    <message>
        <source>MEASURE CIRCLE OUTSIDE</source>
        <translation>MESSEN KREIS AUSSEN</translation>
    </message>
    <message>
        <source>MEASURE INSIDE WIDTH</source>
        <translation>MESSEN BREITE INNEN</translation>
    </message>
    <message>
        <source>MEASURE RIDGE WIDTH</source>
        <translation>MESSEN STEG AUSSEN</translation>
    </message>
    <message>
        <source>cycle {1}: stylus already deflected</source>
        <translation>Zyklus {1}: Taststift bereits ausgelenkt</translation>
    </message>
    <message>
        <source>cycle {1}: touch point not reached within the measuring path DIST = {2} mm</source>
        <translation>Zyklus {1}: Antastpunkt innerhalb des Messwegs DIST = {2} mm nicht erreicht</translation>
    </message>
    <message>
        <source>Measuring height: ball centre in the tool axis</source>
        <translation>Messhöhe: Kugelmitte in der Werkzeugachse</translation>
    </message>
    <message>
        <source>Set-up clearance, added to SET_UP of the probe table</source>
        <translation>Sicherheits-Abstand, zusätzlich zu SET_UP aus der Tastsystemtabelle</translation>
    </message>
    <message>
        <source>Clearance height: no collision with workpiece or fixtures</source>
        <translation>Sichere Höhe: keine Kollision mit Werkstück oder Spannmitteln</translation>
    </message>
    <message>
        <source>Move to clearance height between points: 0 no, 1 yes</source>
        <translation>Zwischen Punkten auf sichere Höhe fahren: 0 nein, 1 ja</translation>
    </message>
    <message>
        <source>Number in table: 0 sets the display (active preset)</source>
        <translation>Nummer in Tabelle: 0 setzt die Anzeige (aktiver Bezugspunkt)</translation>
    </message>
    <message>
        <source>Measured-value transfer: 0 datum table, 1 preset table</source>
        <translation>Messwert-Übergabe: 0 Nullpunkt-Tabelle, 1 Bezugspunkttabelle</translation>
    </message>
    <message>
        <source>New datum in the main axis</source>
        <translation>Neuer Bezugspunkt in der Hauptachse</translation>
    </message>
    <message>
        <source>New datum in the secondary axis</source>
        <translation>Neuer Bezugspunkt in der Nebenachse</translation>
    </message>
    <message>
        <source>New datum in the tool axis</source>
        <translation>Neuer Bezugspunkt in der Werkzeugachse</translation>
    </message>
    <message>
        <source>Probe in the tool axis too: 0 no, 1 yes</source>
        <translation>Auch in der Werkzeugachse antasten: 0 nein, 1 ja</translation>
    </message>
    <message>
        <source>Tool-axis touch point, main axis</source>
        <translation>Antastpunkt Werkzeugachse: Koordinate Hauptachse</translation>
    </message>
    <message>
        <source>Tool-axis touch point, secondary axis</source>
        <translation>Antastpunkt Werkzeugachse: Koordinate Nebenachse</translation>
    </message>
    <message>
        <source>Tool-axis touch point, nominal surface in the tool axis</source>
        <translation>Antastpunkt Werkzeugachse: Soll-Oberfläche in der Werkzeugachse</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main axis, 2 secondary axis</source>
        <translation>Messachse: 1 Hauptachse, 2 Nebenachse</translation>
    </message>
    <message>
        <source>Traverse direction toward the workpiece: -1 or +1</source>
        <translation>Verfahrrichtung zum Werkstück: -1 oder +1</translation>
    </message>
    <message>
        <source>Starting angle: main axis to touch point 1</source>
        <translation>Startwinkel: Hauptachse zu Antastpunkt 1</translation>
    </message>
    <message>
        <source>Stepping angle between touch points (sign = direction)</source>
        <translation>Winkelschritt zwischen den Antastpunkten (Vorzeichen = Richtung)</translation>
    </message>
    <message>
        <source>Number of touch points in the plane: 3 or 4</source>
        <translation>Anzahl der Antastpunkte in der Ebene: 3 oder 4</translation>
    </message>
    <message>
        <source>Path between points: 0 straight line, 1 arc</source>
        <translation>Bahn zwischen den Punkten: 0 Gerade, 1 Kreisbogen</translation>
    </message>
    <message>
        <source>Measuring log: 0 none, 1 write TCHPRnnn.TXT, 2 also stop</source>
        <translation>Messprotokoll: 0 keins, 1 TCHPRnnn.TXT schreiben, 2 zusätzlich anhalten</translation>
    </message>
    <message>
        <source>PGM stop on tolerance error: 0 no, 1 yes</source>
        <translation>PGM-Stopp bei Toleranzfehler: 0 nein, 1 ja</translation>
    </message>
    <message>
        <source>Tool for monitoring: 0 none</source>
        <translation>Werkzeug für Überwachung: 0 keins</translation>
    </message>
    <message>
        <source>PROBE expected after TCH</source>
        <translation>PROBE nach TCH erwartet</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: call the touch probe with TOOL CALL first (it defines the probe axis)</source>
        <translation>Tastsystemzyklus {1}: zuerst das Tastsystem mit TOOL CALL aufrufen (es legt die Tastsystemachse fest)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: probe {2} is not in tchprobe.tp</source>
        <translation>Tastsystemzyklus {1}: Tastsystem {2} ist nicht in tchprobe.tp</translation>
    </message>
    <message>
        <source>touch probe cycle {1} is not supported yet</source>
        <translation>Tastsystemzyklus {1} wird noch nicht unterstützt</translation>
    </message>
    <message>
        <source>{1}: Q{2} is PREDEF but GLOBAL DEF 120 gives no value</source>
        <translation>{1}: Q{2} ist PREDEF, aber GLOBAL DEF 120 liefert keinen Wert</translation>
    </message>
    <message>
        <source>{1}: probing is not possible while a coordinate transformation is active (cycles 7, 8, 10, 11, 26)</source>
        <translation>{1}: Antasten ist nicht möglich, solange eine Koordinatenumrechnung aktiv ist (Zyklen 7, 8, 10, 11, 26)</translation>
    </message>
    <message>
        <source>{1}: probing runs with tool axis Z only so far</source>
        <translation>{1}: Antasten funktioniert bisher nur mit Werkzeugachse Z</translation>
    </message>
    <message>
        <source>cannot write the measuring log {1}: {2}</source>
        <translation>Messprotokoll {1} kann nicht geschrieben werden: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the preset table: {2}</source>
        <translation>Tastsystemzyklus {1}: die Bezugspunkttabelle kann nicht geschrieben werden: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1} is not supported yet; the program cannot run past this block</source>
        <translation>Tastsystemzyklus {1} wird noch nicht unterstützt; das Programm kann nicht über diesen Satz hinaus laufen</translation>
    </message>
    <message>
        <source>{1} must be an array of three numbers [x, y, z], not {2}</source>
        <translation>{1} muss eine Liste aus drei Zahlen [x, y, z] sein, nicht {2}</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine X; write shift = [x, y, z]</source>
        <translation>Simulation: wie weit das reale Rohteil in Maschinen-X von seiner programmierten Lage abweicht; shift = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine Y; write shift = [x, y, z]</source>
        <translation>Simulation: wie weit das reale Rohteil in Maschinen-Y von seiner programmierten Lage abweicht; shift = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine Z; write shift = [x, y, z]</source>
        <translation>Simulation: wie weit das reale Rohteil in Maschinen-Z von seiner programmierten Lage abweicht; shift = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank is turned about the tool axis, through its programmed origin</source>
        <translation>Simulation: wie weit das reale Rohteil um die Werkzeugachse durch seinen programmierten Nullpunkt gedreht ist</translation>
    </message>
    <message>
        <source>X of the start point</source>
        <translation>X des Startpunkts</translation>
    </message>
    <message>
        <source>Z of the start point</source>
        <translation>Z des Startpunkts</translation>
    </message>
    <message>
        <source>Program that holds the profile</source>
        <translation>Programm, das das Profil enthält</translation>
    </message>
    <message>
        <source>X of the end point</source>
        <translation>X des Endpunkts</translation>
    </message>
    <message>
        <source>Peck reduction factor (tapping: tapping type)</source>
        <translation>Abnahmefaktor der Bohrschritte (Gewindebohren: Art des Gewindebohrens)</translation>
    </message>
    <message>
        <source>Z of the end point</source>
        <translation>Z des Endpunkts</translation>
    </message>
    <message>
        <source>Label of the first profile block</source>
        <translation>Marke des ersten Profilsatzes</translation>
    </message>
    <message>
        <source>Minimum infeed increment</source>
        <translation>Kleinste Zustellung</translation>
    </message>
    <message>
        <source>Label of the last profile block</source>
        <translation>Marke des letzten Profilsatzes</translation>
    </message>
    <message>
        <source>Pass step</source>
        <translation>Zustellung je Durchgang</translation>
    </message>
    <message>
        <source>Maximum pass step</source>
        <translation>Maximale Zustellung je Durchgang</translation>
    </message>
    <message>
        <source>Rapid approach to the previous peck</source>
        <translation>Eilgang-Annäherung an den vorigen Bohrschritt</translation>
    </message>
    <message>
        <source>Thread pitch</source>
        <translation>Gewindesteigung</translation>
    </message>
    <message>
        <source>Maximum step between plunges</source>
        <translation>Maximaler Abstand zwischen den Einstichen</translation>
    </message>
    <message>
        <source>Stock to remove</source>
        <translation>Abzutragendes Material</translation>
    </message>
    <message>
        <source>X distance from the start point to the arc centre</source>
        <translation>X-Abstand vom Startpunkt zum Kreismittelpunkt</translation>
    </message>
    <message>
        <source>Depth from the start point</source>
        <translation>Tiefe ab dem Startpunkt</translation>
    </message>
    <message>
        <source>Total thread depth</source>
        <translation>Gesamte Gewindetiefe</translation>
    </message>
    <message>
        <source>Feed for plunging into valleys</source>
        <translation>Vorschub beim Eintauchen in Täler</translation>
    </message>
    <message>
        <source>Z distance from the start point to the arc centre</source>
        <translation>Z-Abstand vom Startpunkt zum Kreismittelpunkt</translation>
    </message>
    <message>
        <source>Measured point of a thread to repass</source>
        <translation>Messpunkt eines nachzuschneidenden Gewindes</translation>
    </message>
    <message>
        <source>Dwell at the bottom</source>
        <translation>Verweilzeit am Grund</translation>
    </message>
    <message>
        <source>Infeed angle</source>
        <translation>Zustellwinkel</translation>
    </message>
    <message>
        <source>Main machining axis (0: Z, 1: X)</source>
        <translation>Hauptbearbeitungsachse (0: Z, 1: X)</translation>
    </message>
    <message>
        <source>Finishing allowance in X</source>
        <translation>Schlichtaufmaß in X</translation>
    </message>
    <message>
        <source>Minimum peck depth</source>
        <translation>Minimale Bohrschritttiefe</translation>
    </message>
    <message>
        <source>Finishing pass allowance</source>
        <translation>Aufmaß für den Schlichtdurchgang</translation>
    </message>
    <message>
        <source>Finishing allowance in Z</source>
        <translation>Schlichtaufmaß in Z</translation>
    </message>
    <message>
        <source>Pitch change per revolution</source>
        <translation>Steigungsänderung pro Umdrehung</translation>
    </message>
    <message>
        <source>Rapid retract after each peck</source>
        <translation>Eilgang-Rückzug nach jedem Bohrschritt</translation>
    </message>
    <message>
        <source>Feed of the finishing pass</source>
        <translation>Vorschub des Schlichtdurchgangs</translation>
    </message>
    <message>
        <source>Feed of the final roughing pass</source>
        <translation>Vorschub des letzten Schruppdurchgangs</translation>
    </message>
    <message>
        <source>Safety distance from the thread start</source>
        <translation>Sicherheitsabstand zum Gewindeanfang</translation>
    </message>
    <message>
        <source>Safety distance for the retract</source>
        <translation>Sicherheitsabstand für den Rückzug</translation>
    </message>
    <message>
        <source>Peck depth (0: tapping)</source>
        <translation>Bohrschritttiefe (0: Gewindebohren)</translation>
    </message>
    <message>
        <source>Depth of the first pass (negative: constant step)</source>
        <translation>Tiefe des ersten Durchgangs (negativ: konstante Zustellung)</translation>
    </message>
    <message>
        <source>Thread run-out</source>
        <translation>Gewindeauslauf</translation>
    </message>
    <message>
        <source>Spindle angle at the start or measured point</source>
        <translation>Spindelwinkel am Start- oder Messpunkt</translation>
    </message>
    <message>
        <source>Number of thread starts</source>
        <translation>Anzahl der Gewindegänge</translation>
    </message>
    <message>
        <source>One value per field</source>
        <translation>Ein Wert pro Feld</translation>
    </message>
    <message>
        <source>Canned
cycles</source>
        <translation>Fest-
zyklen</translation>
    </message>
    <message>
        <source>Put the cursor on a canned cycle block (G66-G89) to edit it.</source>
        <translation>Den Cursor auf einen Festzyklus-Satz (G66-G89) setzen, um ihn zu bearbeiten.</translation>
    </message>
    <message>
        <source>JOG</source>
        <translation>JOG</translation>
    </message>
    <message>
        <source>MDI</source>
        <translation>MDI</translation>
    </message>
    <message>
        <source>Single-block execution</source>
        <translation>Einzelsatzausführung</translation>
    </message>
    <message>
        <source>Automatic execution</source>
        <translation>Automatische Ausführung</translation>
    </message>
    <message>
        <source>Editing</source>
        <translation>Editieren</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>Label numbers of the contour subprograms (up to 12, separated by /)</source>
        <translation>Labelnummern der Kontur-Unterprogramme (bis zu 12, durch / getrennt)</translation>
    </message>
    <message>
        <source>Inside corner rounding radius</source>
        <translation>Rundungsradius an Innenecken</translation>
    </message>
    <message>
        <source>CONTOUR</source>
        <translation>KONTUR</translation>
    </message>
    <message>
        <source>CONTOUR DATA</source>
        <translation>KONTUR-DATEN</translation>
    </message>
    <message>
        <source>Rough-out tool number (0: the tool in the spindle)</source>
        <translation>Nummer des Räumwerkzeugs (0: Werkzeug in der Spindel)</translation>
    </message>
    <message>
        <source>cycle {1} needs a pocket among the contours of cycle 14</source>
        <translation>Zyklus {1} braucht eine Tasche unter den Konturen von Zyklus 14</translation>
    </message>
    <message>
        <source>cycle {1}: tool {2} ({3}) is not in the tool table</source>
        <translation>Zyklus {1}: Werkzeug {2} ({3}) ist nicht in der Werkzeugtabelle</translation>
    </message>
    <message>
        <source>PILOT DRILLING</source>
        <translation>VORBOHREN</translation>
    </message>
    <message>
        <source>Coarse roughing tool number (0: none)</source>
        <translation>Nummer des Vorräumwerkzeugs (0: keines)</translation>
    </message>
    <message>
        <source>Feed rate for reciprocation</source>
        <translation>Vorschub Pendeln</translation>
    </message>
    <message>
        <source>Feed rate factor in %</source>
        <translation>Vorschubfaktor in %</translation>
    </message>
    <message>
        <source>Fine roughing strategy (0 along the contour, 1 retract between areas)</source>
        <translation>Nachräumstrategie (0 entlang der Kontur, 1 Abheben zwischen den Bereichen)</translation>
    </message>
    <message>
        <source>cycle {1}: the feed rate for reciprocation Q19 needs the plunge angle ANGLE of the tool</source>
        <translation>Zyklus {1}: der Vorschub Pendeln Q19 braucht den Eintauchwinkel ANGLE des Werkzeugs</translation>
    </message>
    <message>
        <source>ROUGH-OUT</source>
        <translation>RAEUMEN</translation>
    </message>
    <message>
        <source>FLOOR FINISHING</source>
        <translation>SCHLICHTEN TIEFE</translation>
    </message>
    <message>
        <source>SIDE FINISHING</source>
        <translation>SCHLICHTEN SEITE</translation>
    </message>
    <message>
        <source>cycle {1} needs cycle 20 CONTOUR DATA before it</source>
        <translation>Zyklus {1} braucht davor Zyklus 20 KONTUR-DATEN</translation>
    </message>
    <message>
        <source>cycle {1} needs cycle 14 CONTOUR before it</source>
        <translation>Zyklus {1} braucht davor Zyklus 14 KONTUR</translation>
    </message>
    <message>
        <source>cycle {1}: the islands of cycle 14 cover the whole pocket</source>
        <translation>Zyklus {1}: die Inseln von Zyklus 14 bedecken die ganze Tasche</translation>
    </message>
    <message>
        <source>Retraction feed rate (0: milling feed)</source>
        <translation>Vorschub Rückzug (0: Fräsvorschub)</translation>
    </message>
    <message>
        <source>cycle 14: a label number from 1 to 65535 expected</source>
        <translation>Zyklus 14: eine Labelnummer von 1 bis 65535 erwartet</translation>
    </message>
    <message>
        <source>cycle 14: label numbers are separated by &apos;/&apos;</source>
        <translation>Zyklus 14: Labelnummern werden durch &apos;/&apos; getrennt</translation>
    </message>
    <message>
        <source>cycle 14 lists 1 to 12 label numbers</source>
        <translation>Zyklus 14 nennt 1 bis 12 Labelnummern</translation>
    </message>
    <message>
        <source>this block is not allowed in a contour subprogram</source>
        <translation>dieser Satz ist in einem Kontur-Unterprogramm nicht erlaubt</translation>
    </message>
    <message>
        <source>a contour subprogram must not move in the tool axis</source>
        <translation>ein Kontur-Unterprogramm darf nicht in der Werkzeugachse verfahren</translation>
    </message>
    <message>
        <source>the first block of a contour subprogram must be a straight line with both working-plane axes</source>
        <translation>der erste Satz eines Kontur-Unterprogramms muss eine Gerade mit beiden Achsen der Bearbeitungsebene sein</translation>
    </message>
    <message>
        <source>a contour subprogram has more than 16384 blocks</source>
        <translation>ein Kontur-Unterprogramm hat mehr als 16384 Sätze</translation>
    </message>
    <message>
        <source>the contour subprogram LBL {1} needs radius compensation RL or RR (pocket or island)</source>
        <translation>das Kontur-Unterprogramm LBL {1} braucht Radiuskorrektur RL oder RR (Tasche oder Insel)</translation>
    </message>
    <message>
        <source>MILLING DEPTH</source>
        <translation>FRAESTIEFE</translation>
    </message>
    <message>
        <source>TOOL PATH OVERLAP</source>
        <translation>BAHN-UEBERLAPPUNG</translation>
    </message>
    <message>
        <source>CLEARANCE HEIGHT</source>
        <translation>SICHERE HOEHE</translation>
    </message>
    <message>
        <source>ROUNDING RADIUS</source>
        <translation>RUNDUNGSRADIUS</translation>
    </message>
    <message>
        <source>ROTATIONAL DIRECTION</source>
        <translation>DREHSINN</translation>
    </message>
    <message>
        <source>FEED RATE F. ROUGHNG</source>
        <translation>VORSCHUB RAEUMEN</translation>
    </message>
    <message>
        <source>ROUGH-OUT TOOL</source>
        <translation>RAEUMWERKZEUG</translation>
    </message>
    <message>
        <source>COARSE ROUGHING TOOL</source>
        <translation>VORRAEUM-WERKZEUG</translation>
    </message>
    <message>
        <source>FEED RATE FOR RECIP.</source>
        <translation>VORSCHUB PENDELN</translation>
    </message>
    <message>
        <source>FINE ROUGH STRATEGY</source>
        <translation>NACHRAEUMSTRATEGIE</translation>
    </message>
    <message>
        <source>after G00 the raw-stock profile needs G01, G02 or G03</source>
        <translation>nach G00 braucht das Rohteilprofil G01, G02 oder G03</translation>
    </message>
    <message>
        <source>An ISO block is either absolute (G90) or incremental (G91): enter all coordinates with I or none</source>
        <translation>Ein ISO-Satz ist entweder absolut (G90) oder inkremental (G91): alle Koordinaten mit I eingeben oder keine</translation>
    </message>
    <message>
        <source>ISO programs have no FAUTO: enter the feed</source>
        <translation>ISO-Programme kennen kein FAUTO: Vorschub eingeben</translation>
    </message>
    <message>
        <source>This cycle has no ISO form</source>
        <translation>Dieser Zyklus hat keine ISO-Form</translation>
    </message>
    <message>
        <source>This block has no ISO form</source>
        <translation>Dieser Satz hat keine ISO-Form</translation>
    </message>
    <message>
        <source>FK: the relative data refer to block {1}, which is not among the last 64 determined blocks</source>
        <translation>FK: Die relativen Daten beziehen sich auf Satz {1}, der nicht unter den letzten 64 bestimmten Sätzen ist</translation>
    </message>
    <message>
        <source>FK: polar data need a pole FPOL</source>
        <translation>FK: Polare Daten brauchen einen Pol FPOL</translation>
    </message>
    <message>
        <source>FK: this element has {1} solutions: choose one with FSELECT in the next block</source>
        <translation>FK: Dieses Element hat {1} Lösungen: eine mit FSELECT im nächsten Satz wählen</translation>
    </message>
    <message>
        <source>FK: R and LEN must be positive, D must not be negative</source>
        <translation>FK: R und LEN müssen positiv sein, D darf nicht negativ sein</translation>
    </message>
    <message>
        <source>FK: CLSD- without a CLSD+ before it</source>
        <translation>FK: CLSD- ohne vorheriges CLSD+</translation>
    </message>
    <message>
        <source>FSELECT without an FK element with several solutions before it</source>
        <translation>FSELECT ohne vorheriges FK-Element mit mehreren Lösungen</translation>
    </message>
    <message>
        <source>FSELECT {1}: the element has {2} solutions</source>
        <translation>FSELECT {1}: Das Element hat {2} Lösungen</translation>
    </message>
    <message>
        <source>FK: this element is not determined: the FK sequence ends before enough data are given</source>
        <translation>FK: Dieses Element ist nicht bestimmt: die FK-Folge endet, bevor genug Daten gegeben sind</translation>
    </message>
    <message>
        <source>FK: this element is not determined by the blocks that follow it</source>
        <translation>FK: Dieses Element wird durch die folgenden Sätze nicht bestimmt</translation>
    </message>
    <message>
        <source>FK: the data of this block contradict the contour: no solution</source>
        <translation>FK: Die Daten dieses Satzes widersprechen der Kontur: keine Lösung</translation>
    </message>
    <message>
        <source>FSELECT needs the number of a solution (1 to 99)</source>
        <translation>FSELECT braucht die Nummer einer Lösung (1 bis 99)</translation>
    </message>
    <message>
        <source>unexpected text</source>
        <translation>unerwarteter Text</translation>
    </message>
    <message>
        <source>FPOL takes X and Y once each</source>
        <translation>FPOL nimmt X und Y je einmal</translation>
    </message>
    <message>
        <source>FPOL needs X and Y</source>
        <translation>FPOL braucht X und Y</translation>
    </message>
    <message>
        <source>this FK datum is programmed twice</source>
        <translation>Diese FK-Angabe ist zweimal programmiert</translation>
    </message>
    <message>
        <source>CLSD+ or CLSD- expected</source>
        <translation>CLSD+ oder CLSD- erwartet</translation>
    </message>
    <message>
        <source>the block number relative data refer to expected</source>
        <translation>Satznummer erwartet, auf die sich die relativen Daten beziehen</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in an FK block</source>
        <translation>unerwartetes &apos;{1}&apos; in einem FK-Satz</translation>
    </message>
    <message>
        <source>P{1}X and P{1}Y are given together</source>
        <translation>P{1}X und P{1}Y werden zusammen angegeben</translation>
    </message>
    <message>
        <source>{1} needs an incremental value {2} in the same block</source>
        <translation>{1} braucht einen inkrementalen Wert {2} im selben Satz</translation>
    </message>
    <message>
        <source>1st touch point, nominal surface in the tool axis</source>
        <translation>1. Antastpunkt: Soll-Oberfläche in der Werkzeugachse</translation>
    </message>
    <message>
        <source>2nd touch point, nominal surface in the tool axis</source>
        <translation>2. Antastpunkt: Soll-Oberfläche in der Werkzeugachse</translation>
    </message>
    <message>
        <source>3rd touch point, nominal surface in the tool axis</source>
        <translation>3. Antastpunkt: Soll-Oberfläche in der Werkzeugachse</translation>
    </message>
    <message>
        <source>cycle {1}: the three touch points lie on one line</source>
        <translation>Zyklus {1}: die drei Antastpunkte liegen auf einer Geraden</translation>
    </message>
    <message>
        <source>MEASURE BOLT HOLE CIRC</source>
        <translation>MESSEN LOCHKREIS</translation>
    </message>
    <message>
        <source>MEASURE PLANE</source>
        <translation>MESSEN EBENE</translation>
    </message>
    <message>
        <source>1st centre, main axis</source>
        <translation>1. Mitte Hauptachse</translation>
    </message>
    <message>
        <source>1st centre, secondary axis</source>
        <translation>1. Mitte Nebenachse</translation>
    </message>
    <message>
        <source>2nd centre, main axis</source>
        <translation>2. Mitte Hauptachse</translation>
    </message>
    <message>
        <source>2nd centre, secondary axis</source>
        <translation>2. Mitte Nebenachse</translation>
    </message>
    <message>
        <source>Compensation: 0 basic rotation, 1 rotary table</source>
        <translation>Kompensation: 0 Grunddrehung, 1 Rundtisch</translation>
    </message>
    <message>
        <source>Set the rotary axis display to 0 after alignment: 0 no, 1 yes</source>
        <translation>Anzeige der Drehachse nach dem Ausrichten auf 0 setzen: 0 nein, 1 ja</translation>
    </message>
    <message>
        <source>Diameter of stud 1 (rather too large)</source>
        <translation>Durchmesser Zapfen 1 (eher zu groß)</translation>
    </message>
    <message>
        <source>Diameter of stud 2 (rather too large)</source>
        <translation>Durchmesser Zapfen 2 (eher zu groß)</translation>
    </message>
    <message>
        <source>Measuring height at stud 2: ball centre in the tool axis</source>
        <translation>Messhöhe am Zapfen 2: Kugelmitte in der Werkzeugachse</translation>
    </message>
    <message>
        <source>3rd centre, main axis</source>
        <translation>3. Mitte Hauptachse</translation>
    </message>
    <message>
        <source>3rd centre, secondary axis</source>
        <translation>3. Mitte Nebenachse</translation>
    </message>
    <message>
        <source>4th centre, main axis</source>
        <translation>4. Mitte Hauptachse</translation>
    </message>
    <message>
        <source>4th centre, secondary axis</source>
        <translation>4. Mitte Nebenachse</translation>
    </message>
    <message>
        <source>ROT 2 HOLES</source>
        <translation>ROT 2 BOHRUNGEN</translation>
    </message>
    <message>
        <source>ROT 2 STUDS</source>
        <translation>ROT 2 ZAPFEN</translation>
    </message>
    <message>
        <source>DATUM FROM 4 HOLES</source>
        <translation>BEZUGSPUNKT MITTE 4 BOHRUNGEN</translation>
    </message>
    <message>
        <source>Width of the slot or ridge, whatever its orientation</source>
        <translation>Breite der Nut oder des Stegs, unabhängig von ihrer Lage</translation>
    </message>
    <message>
        <source>New datum in the measuring axis for the centre</source>
        <translation>Neuer Bezugspunkt in der Messachse für die Mitte</translation>
    </message>
    <message>
        <source>SLOT CENTER REF PT</source>
        <translation>BEZUGSPUNKT MITTE NUT</translation>
    </message>
    <message>
        <source>RIDGE CENTER REF PT</source>
        <translation>BEZUGSPUNKT MITTE STEG</translation>
    </message>
    <message>
        <source>Tool measurement: 0 write L/R, 1 compare and write DL/DR, 2 compare</source>
        <translation>Werkzeugmessung: 0 L/R schreiben, 1 vergleichen und DL/DR schreiben, 2 vergleichen</translation>
    </message>
    <message>
        <source>Probe each tooth: 0 no, 1 yes</source>
        <translation>Einzelschneiden antasten: 0 nein, 1 ja</translation>
    </message>
    <message>
        <source>CALIBRATE TT</source>
        <translation>TT KALIBRIEREN</translation>
    </message>
    <message>
        <source>TOOL LENGTH</source>
        <translation>WERKZEUG-LAENGE</translation>
    </message>
    <message>
        <source>TOOL RADIUS</source>
        <translation>WERKZEUG-RADIUS</translation>
    </message>
    <message>
        <source>MEASURE TOOL</source>
        <translation>WERKZEUG MESSEN</translation>
    </message>
    <message>
        <source>TCH PROBE {1}.{2} without TCH PROBE {1}.0 before it</source>
        <translation>TCH PROBE {1}.{2} ohne vorheriges TCH PROBE {1}.0</translation>
    </message>
    <message>
        <source>{1}.{2}: a number after &apos;:&apos; expected</source>
        <translation>{1}.{2}: nach &apos;:&apos; wird eine Zahl erwartet</translation>
    </message>
    <message>
        <source>{1}: sub-blocks .1, .2 and .3 are needed</source>
        <translation>{1}: die Teilsätze .1, .2 und .3 werden benötigt</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the machine has no tool touch probe ([simulation.tool_probe] enabled = true)</source>
        <translation>Tastsystemzyklus {1}: die Maschine hat kein Werkzeug-Tastsystem ([simulation.tool_probe] enabled = true)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: tool measurement is not possible while mirroring or scaling is active (cycles 8, 11, 26)</source>
        <translation>Tastsystemzyklus {1}: Werkzeugvermessung ist bei aktiver Spiegelung oder Maßfaktor nicht möglich (Zyklen 8, 11, 26)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: probing runs with tool axis Z only so far</source>
        <translation>Tastsystemzyklus {1}: Antasten läuft bisher nur mit Werkzeugachse Z</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: call the tool to be measured from the tool table TOOL.T with TOOL CALL first</source>
        <translation>Tastsystemzyklus {1}: zuerst das zu vermessende Werkzeug aus der Werkzeugtabelle TOOL.T mit TOOL CALL aufrufen</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the tool table: {2}</source>
        <translation>Tastsystemzyklus {1}: die Werkzeugtabelle kann nicht geschrieben werden: {2}</translation>
    </message>
    <message>
        <source>{1} must be tables [[{1}]] with tool, length and radius</source>
        <translation>{1} müssen Tabellen [[{1}]] mit tool, length und radius sein</translation>
    </message>
    <message>
        <source>{1} = {2} is out of range: a tool number 0 ... 32767, lengths within +-10 mm</source>
        <translation>{1} = {2} liegt außerhalb des Bereichs: eine Werkzeugnummer 0 ... 32767, Längen innerhalb +-10 mm</translation>
    </message>
    <message>
        <source>{1} needs a tool number</source>
        <translation>{1} braucht eine Werkzeugnummer</translation>
    </message>
    <message>
        <source>{1}: tool {2} is given twice</source>
        <translation>{1}: Werkzeug {2} ist zweimal angegeben</translation>
    </message>
    <message>
        <source>Simulation: the machine has a tool touch probe (TT) for the tool measuring cycles 30-33 and 480-483</source>
        <translation>Simulation: die Maschine hat ein Werkzeug-Tastsystem (TT) für die Werkzeugmesszyklen 30-33 und 480-483</translation>
    </message>
    <message>
        <source>TT: machine X of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: Maschinen-X der Mitte der Messfläche; centre = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>TT: machine Y of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: Maschinen-Y der Mitte der Messfläche; centre = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>TT: machine Z of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: Maschinen-Z der Mitte der Messfläche; centre = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>TT: diameter of the disc stylus (side of a cube stylus)</source>
        <translation>TT: Durchmesser des Scheiben-Tasters (Seite eines Würfel-Tasters)</translation>
    </message>
    <message>
        <source>TT: stylus shape, a disc or a cube</source>
        <translation>TT: Form des Tasters, Scheibe oder Würfel</translation>
    </message>
    <message>
        <source>TT: how far below the top of the stylus the end face of the tool sits when its radius is measured</source>
        <translation>TT: wie weit unter der Oberkante des Tasters die Stirnseite des Werkzeugs bei der Radiusmessung steht</translation>
    </message>
    <message>
        <source>TT: safety zone above the stylus, and how far before the stylus each touch starts</source>
        <translation>TT: Sicherheitszone über dem Taster, und wie weit vor dem Taster jede Antastung beginnt</translation>
    </message>
    <message>
        <source>TT: highest cutting-edge speed of a rotating tool; sets the measuring speed</source>
        <translation>TT: höchste Schneidengeschwindigkeit eines drehenden Werkzeugs; legt die Messdrehzahl fest</translation>
    </message>
    <message>
        <source>TT: measuring error allowed with a rotating tool; probing feed = tolerance x speed</source>
        <translation>TT: zulässiger Messfehler bei drehendem Werkzeug; Antastvorschub = Toleranz x Drehzahl</translation>
    </message>
    <message>
        <source>TT: probing feed with a stationary spindle</source>
        <translation>TT: Antastvorschub bei stehender Spindel</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the tool to monitor (Q330 = {2}) is not in the tool table</source>
        <translation>Tastsystemzyklus {1}: das zu überwachende Werkzeug (Q330 = {2}) ist nicht in der Werkzeugtabelle</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: tool {2} is broken (deviation {3} mm beyond RBREAK); it is locked</source>
        <translation>Tastsystemzyklus {1}: Werkzeug {2} ist gebrochen (Abweichung {3} mm über RBREAK); es ist gesperrt</translation>
    </message>
    <message>
        <source>Climb or up-cut (+1 climb, -1 up-cut, 0 alternating)</source>
        <translation>Gleichlauf oder Gegenlauf (+1 Gleichlauf, -1 Gegenlauf, 0 abwechselnd)</translation>
    </message>
    <message>
        <source>Accepted residual material</source>
        <translation>Akzeptiertes Restmaterial</translation>
    </message>
    <message>
        <source>Maximum connection distance</source>
        <translation>Maximaler Verbindungsabstand</translation>
    </message>
    <message>
        <source>Path extension</source>
        <translation>Bahnverlängerung</translation>
    </message>
    <message>
        <source>cycle {1}: with cycle 270 the contour subprogram must be programmed without RL/RR (Q391 gives the side)</source>
        <translation>Zyklus {1}: mit Zyklus 270 muss das Kontur-Unterprogramm ohne RL/RR programmiert sein (Q391 gibt die Seite vor)</translation>
    </message>
    <message>
        <source>CONTOUR TRAIN</source>
        <translation>KONTUR-ZUG</translation>
    </message>
    <message>
        <source>Type of approach/departure (1 arc, 2 tangent line, 3 perpendicular)</source>
        <translation>Art der An-/Wegfahrt (1 Kreisbogen, 2 tangentiale Gerade, 3 senkrecht)</translation>
    </message>
    <message>
        <source>Radius compensation (0 R0, 1 RL, 2 RR)</source>
        <translation>Radiuskorrektur (0 R0, 1 RL, 2 RR)</translation>
    </message>
    <message>
        <source>Radius of the approach/departure arc</source>
        <translation>Radius des An-/Wegfahrkreises</translation>
    </message>
    <message>
        <source>Centre angle of the approach/departure arc</source>
        <translation>Mittelpunktswinkel des An-/Wegfahrkreises</translation>
    </message>
    <message>
        <source>Distance of the auxiliary point</source>
        <translation>Abstand des Hilfspunkts</translation>
    </message>
    <message>
        <source>CONTOUR TRAIN DATA</source>
        <translation>KONTURZUG-DATEN</translation>
    </message>
    <message>
        <source>cycle {1}: cycle 14 must list exactly one contour subprogram (the slot&apos;s centre line)</source>
        <translation>Zyklus {1}: Zyklus 14 muss genau ein Kontur-Unterprogramm enthalten (die Mittellinie der Nut)</translation>
    </message>
    <message>
        <source>cycle {1}: the start point of a closed slot must not lie on a corner of the contour</source>
        <translation>Zyklus {1}: der Startpunkt einer geschlossenen Nut darf nicht auf einer Konturecke liegen</translation>
    </message>
    <message>
        <source>cycle {1}: the plunging depth Q202 must be greater than 0</source>
        <translation>Zyklus {1}: die Zustell-Tiefe Q202 muss größer als 0 sein</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width less the side allowances is more than twice the tool diameter</source>
        <translation>Zyklus {1}: die Nutbreite abzüglich der Aufmaße Seite ist größer als der doppelte Werkzeugdurchmesser</translation>
    </message>
    <message>
        <source>cycle {1}: the infeed per revolution Q436 must be greater than 0</source>
        <translation>Zyklus {1}: die Zustellung pro Umdrehung Q436 muss größer als 0 sein</translation>
    </message>
    <message>
        <source>Infeed per revolution (trochoidal loop)</source>
        <translation>Zustellung pro Umdrehung (Trochoidalschleife)</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 no function, 2 reciprocating)</source>
        <translation>Eintauchstrategie (0 senkrecht, 1 ohne Funktion, 2 pendelnd)</translation>
    </message>
    <message>
        <source>TROCHOIDAL SLOT</source>
        <translation>KONTURNUT TROCHOIDAL</translation>
    </message>
    <message>
        <source>Strategy (0 meander outside, 1 meander on the edge, 2 line by line, 3 line by line to the edge, 4 spiral)</source>
        <translation>Strategie (0 mäanderförmig außen, 1 mäanderförmig am Rand, 2 zeilenweise, 3 zeilenweise bis zum Rand, 4 spiralförmig)</translation>
    </message>
    <message>
        <source>Milling direction (1 main axis, 2 secondary axis)</source>
        <translation>Fräsrichtung (1 Hauptachse, 2 Nebenachse)</translation>
    </message>
    <message>
        <source>1st limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>1. Begrenzung (0 keine, -1/+1 Hauptachse, -2/+2 Nebenachse)</translation>
    </message>
    <message>
        <source>2nd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>2. Begrenzung (0 keine, -1/+1 Hauptachse, -2/+2 Nebenachse)</translation>
    </message>
    <message>
        <source>3rd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>3. Begrenzung (0 keine, -1/+1 Hauptachse, -2/+2 Nebenachse)</translation>
    </message>
    <message>
        <source>Corner radius</source>
        <translation>Eckenradius</translation>
    </message>
    <message>
        <source>cycle {1}: limits Q347-Q349 are not possible with the spiral strategy Q389 = 4</source>
        <translation>Zyklus {1}: Begrenzungen Q347-Q349 sind mit der Spiralstrategie Q389 = 4 nicht möglich</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is too large for the face between its walls</source>
        <translation>Zyklus {1}: das Werkzeug ist zu groß für die Fläche zwischen ihren Wänden</translation>
    </message>
    <message>
        <source>1ST LIMIT</source>
        <translation>1. BEGRENZUNG</translation>
    </message>
    <message>
        <source>2ND LIMIT</source>
        <translation>2. BEGRENZUNG</translation>
    </message>
    <message>
        <source>3RD LIMIT</source>
        <translation>3. BEGRENZUNG</translation>
    </message>
    <message>
        <source>MILLING DIRECTION</source>
        <translation>FRÄSRICHTUNG</translation>
    </message>
    <message>
        <source>TYPE OF APPROACH</source>
        <translation>ANFAHRART</translation>
    </message>
    <message>
        <source>RADIUS COMPENSATION</source>
        <translation>RADIUSKORREKTUR</translation>
    </message>
    <message>
        <source>RADIUS</source>
        <translation>RADIUS</translation>
    </message>
    <message>
        <source>CENTER ANGLE</source>
        <translation>MITTELPUNKTSWINKEL</translation>
    </message>
    <message>
        <source>DISTANCE</source>
        <translation>ABSTAND</translation>
    </message>
    <message>
        <source>INFEED PER REV.</source>
        <translation>ZUST. PRO UMDR.</translation>
    </message>
    <message>
        <source>RESIDUAL MATERIAL</source>
        <translation>RESTMATERIAL</translation>
    </message>
    <message>
        <source>CONNECTION DISTANCE</source>
        <translation>VERBINDUNGSABSTAND</translation>
    </message>
    <message>
        <source>PATH EXTENSION</source>
        <translation>BAHNVERLÄNGERUNG</translation>
    </message>
    <message>
        <source>MILLING STRATEGY</source>
        <translation>FRÄSSTRATEGIE</translation>
    </message>
    <message>
        <source>cycle {1}: cycle 14 must list exactly one contour subprogram</source>
        <translation>Zyklus {1}: Zyklus 14 muss genau ein Kontur-Unterprogramm enthalten</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is below the clearance height Q7 at the call</source>
        <translation>Zyklus {1}: das Werkzeug steht beim Aufruf unterhalb der Sicheren Höhe Q7</translation>
    </message>
    <message>
        <source>3-D CONTOUR TRAIN</source>
        <translation>3D-KONTUR-ZUG</translation>
    </message>
    <message>
        <source>the first block of a 3-D contour subprogram must give the tool axis too</source>
        <translation>der erste Satz eines 3D-Kontur-Unterprogramms muss auch die Werkzeugachse enthalten</translation>
    </message>
    <message>
        <source>PLANE: SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL or RESET expected</source>
        <translation>PLANE: SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL oder RESET erwartet</translation>
    </message>
    <message>
        <source>PLANE {1}: {2} expected</source>
        <translation>PLANE {1}: {2} erwartet</translation>
    </message>
    <message>
        <source>PLANE RELATIV: SPA, SPB or SPC expected</source>
        <translation>PLANE RELATIV: SPA, SPB oder SPC erwartet</translation>
    </message>
    <message>
        <source>PLANE AXIAL: an angle of A, B or C expected</source>
        <translation>PLANE AXIAL: ein Winkel von A, B oder C erwartet</translation>
    </message>
    <message>
        <source>SEQ+ or SEQ- expected</source>
        <translation>SEQ+ oder SEQ- erwartet</translation>
    </message>
    <message>
        <source>ROT expected</source>
        <translation>ROT erwartet</translation>
    </message>
    <message>
        <source>PLANE: unexpected &apos;{1}&apos;</source>
        <translation>PLANE: unerwartetes &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>PLANE: MOVE, TURN or STAY expected</source>
        <translation>PLANE: MOVE, TURN oder STAY erwartet</translation>
    </message>
    <message>
        <source>PLANE: the points or vectors do not define a plane</source>
        <translation>PLANE: die Punkte oder Vektoren bestimmen keine Ebene</translation>
    </message>
    <message>
        <source>{1} needs rotary axes: this machine has none</source>
        <translation>{1} braucht Drehachsen: diese Maschine hat keine</translation>
    </message>
    <message>
        <source>{1} needs the rotary tables described in the machine file ([kinematics], docs/machine-config.md)</source>
        <translation>{1} braucht die in der Maschinendatei beschriebenen Rundtische ([kinematics], docs/machine-config.md)</translation>
    </message>
    <message>
        <source>the rotary axes of this machine cannot turn the tool perpendicular to this plane</source>
        <translation>die Drehachsen dieser Maschine können das Werkzeug nicht senkrecht zu dieser Ebene stellen</translation>
    </message>
    <message>
        <source>no solution for the rotary axes lies within their soft limits (and the SEQ chosen): {1}</source>
        <translation>keine Lösung für die Drehachsen liegt innerhalb ihrer Software-Endschalter (und des gewählten SEQ): {1}</translation>
    </message>
    <message>
        <source>PLANE with radius compensation RL/RR: program R0 first</source>
        <translation>PLANE mit Radiuskorrektur RL/RR: zuerst R0 programmieren</translation>
    </message>
    <message>
        <source>cycle 19: unexpected &apos;{1}&apos;</source>
        <translation>Zyklus 19: unerwartetes &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>the move would take axis {1} to {2} deg (machine coordinates), beyond its soft limit {3}</source>
        <translation>der Satz würde die Achse {1} auf {2} Grad (Maschinenkoordinaten) fahren, über ihren Software-Endschalter {3} hinaus</translation>
    </message>
    <message>
        <source>Machine X where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>Maschinen-X, wo sich die Drehachsen treffen; pivot = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Machine Y where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>Maschinen-Y, wo sich die Drehachsen treffen; pivot = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Machine Z where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>Maschinen-Z, wo sich die Drehachsen treffen; pivot = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Rotary: turns without end; no soft limits, M126 takes the short way</source>
        <translation>Drehachse: dreht endlos; keine Software-Endschalter, M126 fährt den kurzen Weg</translation>
    </message>
    <message>
        <source>{1} = true is only allowed on a rotary axis</source>
        <translation>{1} = true ist nur bei einer Drehachse erlaubt</translation>
    </message>
    <message>
        <source>{1} = &quot;{2}&quot; is not an enabled rotary axis of this machine</source>
        <translation>{1} = &quot;{2}&quot; ist keine aktive Drehachse dieser Maschine</translation>
    </message>
    <message>
        <source>kinematics.secondary must be another axis than kinematics.primary</source>
        <translation>kinematics.secondary muss eine andere Achse als kinematics.primary sein</translation>
    </message>
    <message>
        <source>P{1} expected after G18</source>
        <translation>P{1} nach G18 erwartet</translation>
    </message>
    <message>
        <source>Show
solution</source>
        <translation>Lösung
zeigen</translation>
    </message>
    <message>
        <source>Select
solution</source>
        <translation>Lösung
wählen</translation>
    </message>
    <message>
        <source>cycle {1}: the contour formula leaves no area to machine</source>
        <translation>Zyklus {1}: die Konturformel lässt keine Fläche zum Bearbeiten übrig</translation>
    </message>
    <message>
        <source>parentheses nested too deep</source>
        <translation>Klammern zu tief verschachtelt</translation>
    </message>
    <message>
        <source>a contour descriptor QC1 ... QC65535 or &apos;(&apos; expected</source>
        <translation>Konturbeschreibung QC1 ... QC65535 oder &apos;(&apos; erwartet</translation>
    </message>
    <message>
        <source>program name in quotes expected</source>
        <translation>Programmname in Anführungszeichen erwartet</translation>
    </message>
    <message>
        <source>DEPTH value expected</source>
        <translation>Wert für DEPTH erwartet</translation>
    </message>
    <message>
        <source>unexpected text &apos;{1}&apos;</source>
        <translation>unerwarteter Text &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>a contour descriptor QC1 ... QC65535 expected</source>
        <translation>Konturbeschreibung QC1 ... QC65535 erwartet</translation>
    </message>
    <message>
        <source>pocket P1 ... P9 or island I1 ... I9 expected</source>
        <translation>Tasche P1 ... P9 oder Insel I1 ... I9 erwartet</translation>
    </message>
    <message>
        <source>CONTOUR DEF combines at most 9 subcontours</source>
        <translation>CONTOUR DEF verknüpft höchstens 9 Teilkonturen</translation>
    </message>
    <message>
        <source>the first subcontour of CONTOUR DEF must be a pocket (P)</source>
        <translation>die erste Teilkontur von CONTOUR DEF muss eine Tasche (P) sein</translation>
    </message>
    <message>
        <source>CONTOUR DEF needs a pocket P1 = &quot;program&quot;</source>
        <translation>CONTOUR DEF braucht eine Tasche P1 = &quot;Programm&quot;</translation>
    </message>
    <message>
        <source>a contour formula combines at most 128 contours</source>
        <translation>eine Konturformel verknüpft höchstens 128 Konturen</translation>
    </message>
    <message>
        <source>QC{1} is not declared (DECLARE CONTOUR)</source>
        <translation>QC{1} ist nicht deklariert (DECLARE CONTOUR)</translation>
    </message>
    <message>
        <source>the contour formula is too long</source>
        <translation>die Konturformel ist zu lang</translation>
    </message>
    <message>
        <source>cannot read the contour program {1}: {2}</source>
        <translation>das Konturprogramm {1} kann nicht gelesen werden: {2}</translation>
    </message>
    <message>
        <source>the contour program {1} has errors</source>
        <translation>das Konturprogramm {1} enthält Fehler</translation>
    </message>
    <message>
        <source>this block is not allowed in a contour-definition program</source>
        <translation>dieser Satz ist in einem Konturdefinitions-Programm nicht erlaubt</translation>
    </message>
    <message>
        <source>every contour needs a DEPTH when one has it (DEPTH0: the depth of cycle 20)</source>
        <translation>jede Kontur braucht DEPTH, wenn eine es hat (DEPTH0: die Tiefe aus Zyklus 20)</translation>
    </message>
    <message>
        <source>the contour program {1} has no formula QC.. = ...</source>
        <translation>das Konturprogramm {1} hat keine Formel QC.. = ...</translation>
    </message>
    <message>
        <source>the contour program {1} has no contour</source>
        <translation>das Konturprogramm {1} enthält keine Kontur</translation>
    </message>
    <message>
        <source>the contour of {1} lies beyond 1,000,000 mm from the origin</source>
        <translation>die Kontur von {1} liegt weiter als 1.000.000 mm vom Nullpunkt</translation>
    </message>
    <message>
        <source>the contour of {1} encloses no area</source>
        <translation>die Kontur von {1} schließt keine Fläche ein</translation>
    </message>
    <message>
        <source>the contour of {1} intersects itself</source>
        <translation>die Kontur von {1} schneidet sich selbst</translation>
    </message>
    <message>
        <source>no input is asked for</source>
        <translation>es wird keine Eingabe verlangt</translation>
    </message>
    <message>
        <source>a customisation program runs in the user channel: it has no ISO blocks (no motion, no M, S, T)</source>
        <translation>ein Anpassungsprogramm läuft im Anwenderkanal: es hat keine ISO-Sätze (keine Bewegung, kein M, S, T)</translation>
    </message>
    <message>
        <source>{1} is a screen customisation instruction: it runs only in a user customisation program (the user screen)</source>
        <translation>{1} ist eine Anweisung zur Bildschirmanpassung: sie läuft nur in einem Anwender-Anpassungsprogramm (dem Anwenderbild)</translation>
    </message>
    <message>
        <source>screen customisation instructions run only in a user customisation program (the user screen)</source>
        <translation>Anweisungen zur Bildschirmanpassung laufen nur in einem Anwender-Anpassungsprogramm (dem Anwenderbild)</translation>
    </message>
    <message>
        <source>data window {1} is not defined (ODW)</source>
        <translation>das Datenfenster {1} ist nicht definiert (ODW)</translation>
    </message>
    <message>
        <source>WKEY: keys come from the PLC or DNC (KEYSRC), which this control does not have</source>
        <translation>WKEY: die Tasten kommen von der SPS oder DNC (KEYSRC), die diese Steuerung nicht hat</translation>
    </message>
    <message>
        <source>WBUF runs only in the customisation program of the edit mode (USEREDIT)</source>
        <translation>WBUF läuft nur im Anpassungsprogramm der Betriebsart Editieren (USEREDIT)</translation>
    </message>
    <message>
        <source>{1}: inputs are IB0-IB25</source>
        <translation>{1}: Eingaben sind IB0-IB25</translation>
    </message>
    <message>
        <source>customisation instructions take global parameters, not the local P{1}</source>
        <translation>Anpassungsanweisungen nehmen globale Parameter, nicht den lokalen P{1}</translation>
    </message>
    <message>
        <source>input format [-]i.d expected (i integer digits 0-6, d decimals 0-5)</source>
        <translation>Eingabeformat [-]i.d erwartet (i Vorkommastellen 0-6, d Nachkommastellen 0-5)</translation>
    </message>
    <message>
        <source>a softkey text has at most 20 characters</source>
        <translation>ein Softkey-Text hat höchstens 20 Zeichen</translation>
    </message>
    <message>
        <source>only positive values are accepted here</source>
        <translation>hier sind nur positive Werte zulässig</translation>
    </message>
    <message>
        <source>a number is expected</source>
        <translation>eine Zahl wird erwartet</translation>
    </message>
    <message>
        <source>the number does not fit the input format</source>
        <translation>die Zahl passt nicht zum Eingabeformat</translation>
    </message>
    <message>
        <source>Exact radius of the calibration ring or stud</source>
        <translation>Genauer Radius des Kalibrierrings oder -zapfens</translation>
    </message>
    <message>
        <source>Number of touch points on the diameter (0: 4)</source>
        <translation>Anzahl Antastpunkte am Durchmesser (0: 4)</translation>
    </message>
    <message>
        <source>Reference angle: main axis to touch point 1</source>
        <translation>Bezugswinkel: Hauptachse zum 1. Antastpunkt</translation>
    </message>
    <message>
        <source>Datum for the length: height of the ring&apos;s top face</source>
        <translation>Bezugspunkt für die Länge: Höhe der Ringoberfläche</translation>
    </message>
    <message>
        <source>CALIBRATE TS LENGTH</source>
        <translation>TS LÄNGE KALIBRIEREN</translation>
    </message>
    <message>
        <source>CALIBRATE TS IN RING</source>
        <translation>TS IM RING KALIBRIEREN</translation>
    </message>
    <message>
        <source>CALIBRATE TS ON STUD</source>
        <translation>TS AM ZAPFEN KALIBRIEREN</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main axis, 2 secondary axis, 3 touch probe axis</source>
        <translation>Messachse: 1 Hauptachse, 2 Nebenachse, 3 Tastsystemachse</translation>
    </message>
    <message>
        <source>Axis for the compensation: 0 automatic, 4 A, 5 B, 6 C</source>
        <translation>Achse für die Ausgleichsbewegung: 0 automatisch, 4 A, 5 B, 6 C</translation>
    </message>
    <message>
        <source>Set to zero after alignment: 0 no, 1 yes</source>
        <translation>Nach dem Ausrichten auf Null setzen: 0 nein, 1 ja</translation>
    </message>
    <message>
        <source>Reference angle the probed line is aligned to</source>
        <translation>Bezugswinkel, auf den die angetastete Gerade ausgerichtet wird</translation>
    </message>
    <message>
        <source>cycle {1}: Q312 must be 0, 4, 5 or 6</source>
        <translation>Zyklus {1}: Q312 muss 0, 4, 5 oder 6 sein</translation>
    </message>
    <message>
        <source>cycle {1}: the machine has no rotary table axis {2} to compensate the misalignment</source>
        <translation>Zyklus {1}: die Maschine hat keine Rundtischachse {2}, um die Schieflage auszugleichen</translation>
    </message>
    <message>
        <source>cycle {1}: the rotary axis {2} cannot compensate a misalignment about the axis of {3}</source>
        <translation>Zyklus {1}: die Drehachse {2} kann keine Schieflage um die Achse von {3} ausgleichen</translation>
    </message>
    <message>
        <source>Preset rotation angle: the basic rotation to set</source>
        <translation>Drehwinkel: die zu setzende Grunddrehung</translation>
    </message>
    <message>
        <source>Number in table: -1 the active preset, 0 preset 0 and active</source>
        <translation>Nummer in Tabelle: -1 der aktive Bezugspunkt, 0 Bezugspunkt 0 und aktiv</translation>
    </message>
    <message>
        <source>Hole centre, main axis</source>
        <translation>Bohrungsmitte Hauptachse</translation>
    </message>
    <message>
        <source>Hole centre, secondary axis: 0 aligns the hole to +Y</source>
        <translation>Bohrungsmitte Nebenachse: 0 richtet die Bohrung auf +Y aus</translation>
    </message>
    <message>
        <source>Nominal diameter (enter it on the small side)</source>
        <translation>Solldurchmesser (eher zu klein eingeben)</translation>
    </message>
    <message>
        <source>Set to zero after alignment: 0 the C display, n add to datum row n</source>
        <translation>Nach dem Ausrichten Null setzen: 0 die C-Anzeige, n zu Nullpunktzeile n addieren</translation>
    </message>
    <message>
        <source>BASIC ROTATION COMPENSATED VIA ROTARY AXIS</source>
        <translation>GRUNDDREHUNG ÜBER DREHACHSE KOMPENSIEREN</translation>
    </message>
    <message>
        <source>SET BASIC ROTATION</source>
        <translation>GRUNDDREHUNG SETZEN</translation>
    </message>
    <message>
        <source>ROT IN C AXIS</source>
        <translation>ROT ÜBER C-ACHSE</translation>
    </message>
    <message>
        <source>Positioning feed rate of the probe (FMAX: rapid traverse)</source>
        <translation>Positioniervorschub des Tastsystems (FMAX: Eilgang)</translation>
    </message>
    <message>
        <source>Pre-position at machine rapid: 0 no (Q396), 1 yes</source>
        <translation>Vorpositionieren im Maschinen-Eilgang: 0 nein (Q396), 1 ja</translation>
    </message>
    <message>
        <source>Angle tracking: 0 no, 1 orient the probe before each touch</source>
        <translation>Winkelnachführung: 0 nein, 1 Tastsystem vor jedem Antasten orientieren</translation>
    </message>
    <message>
        <source>Automatic interruption: 0 never, 1 when a cycle shows its log</source>
        <translation>Automatische Unterbrechung: 0 nie, 1 wenn ein Zyklus sein Protokoll zeigt</translation>
    </message>
    <message>
        <source>Nominal point, main axis</source>
        <translation>Sollpunkt Hauptachse</translation>
    </message>
    <message>
        <source>Nominal point, secondary axis</source>
        <translation>Sollpunkt Nebenachse</translation>
    </message>
    <message>
        <source>Nominal point, tool axis</source>
        <translation>Sollpunkt Werkzeugachse</translation>
    </message>
    <message>
        <source>Surface normal, main axis component</source>
        <translation>Flächennormale, Komponente Hauptachse</translation>
    </message>
    <message>
        <source>Surface normal, secondary axis component</source>
        <translation>Flächennormale, Komponente Nebenachse</translation>
    </message>
    <message>
        <source>Surface normal, tool axis component</source>
        <translation>Flächennormale, Komponente Werkzeugachse</translation>
    </message>
    <message>
        <source>Tolerance along the normal, e.g. &quot;0.4-0.1&quot;</source>
        <translation>Toleranz entlang der Normalen, z. B. &quot;0.4-0.1&quot;</translation>
    </message>
    <message>
        <source>Tolerance error: 0 nothing, 1 stop, 2 stop on undersize only</source>
        <translation>Toleranzfehler: 0 nichts, 1 Stopp, 2 Stopp nur bei Untermaß</translation>
    </message>
    <message>
        <source>cycle {1}: the surface normal Q581..Q583 is zero</source>
        <translation>Zyklus {1}: die Flächennormale Q581..Q583 ist null</translation>
    </message>
    <message>
        <source>FAST PROBING</source>
        <translation>SCHNELLES ANTASTEN</translation>
    </message>
    <message>
        <source>PROBING IN 3-D</source>
        <translation>ANTASTEN 3D</translation>
    </message>
    <message>
        <source>Stop before running: 0 stop to position the tool, 1 no stop</source>
        <translation>Stopp vor der Ausführung: 0 Stopp zum Positionieren des Werkzeugs, 1 kein Stopp</translation>
    </message>
    <message>
        <source>CALIBRATE IR TT</source>
        <translation>IR-TT KALIBRIEREN</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: Q303 = 0 writes the active datum table: select one with SEL TABLE first</source>
        <translation>Tastsystemzyklus {1}: Q303 = 0 schreibt in die aktive Nullpunkt-Tabelle: zuerst eine mit SEL TABLE wählen</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the datum table: {2}</source>
        <translation>Tastsystemzyklus {1}: die Nullpunkt-Tabelle kann nicht geschrieben werden: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: calibration writes the probe&apos;s row of the tool table TOOL.T: call the probe from it</source>
        <translation>Tastsystemzyklus {1}: die Kalibrierung schreibt die Zeile des Tastsystems in der Werkzeugtabelle TOOL.T: das Tastsystem daraus aufrufen</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the TT calibration: {2}</source>
        <translation>Tastsystemzyklus {1}: die TT-Kalibrierung kann nicht geschrieben werden: {2}</translation>
    </message>
    <message>
        <source>Cylinder radius</source>
        <translation>Zylinderradius</translation>
    </message>
    <message>
        <source>Rotary-axis coordinates in the subprogram: 0 degrees, 1 mm/inch</source>
        <translation>Rundachs-Koordinaten im Unterprogramm: 0 Grad, 1 mm/inch</translation>
    </message>
    <message>
        <source>Ridge width</source>
        <translation>Stegbreite</translation>
    </message>
    <message>
        <source>Tolerance of the slot walls (0: no re-machining)</source>
        <translation>Toleranz der Nutwände (0: keine Nachbearbeitung)</translation>
    </message>
    <message>
        <source>cycle {1}: the cylinder radius Q16 must be greater than 0</source>
        <translation>Zyklus {1}: der Zylinderradius Q16 muss größer als 0 sein</translation>
    </message>
    <message>
        <source>cycle {1}: program the contour subprogram with radius compensation RL or RR</source>
        <translation>Zyklus {1}: das Konturunterprogramm mit Radiuskorrektur RL oder RR programmieren</translation>
    </message>
    <message>
        <source>cycle {1}: the centre line must be an open contour, not end where it starts</source>
        <translation>Zyklus {1}: die Mittellinie muss eine offene Kontur sein und darf nicht an ihrem Anfang enden</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE</source>
        <translation>ZYLINDER-MANTEL</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE SLOT</source>
        <translation>ZYLINDER-MANTEL NUTENFRAESEN</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE RIDGE</source>
        <translation>ZYLINDER-MANTEL STEGFRAESEN</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE CONTOUR</source>
        <translation>ZYLINDER-MANTEL KONTUR</translation>
    </message>
    <message>
        <source>a thread cannot be cut on the development of a cylinder</source>
        <translation>auf der Abwicklung eines Zylinders kann kein Gewinde geschnitten werden</translation>
    </message>
    <message>
        <source>cycle {1} needs a rotary table described in the machine file ([kinematics], docs/machine-config.md)</source>
        <translation>Zyklus {1} braucht einen in der Maschinendatei beschriebenen Rundtisch ([kinematics], docs/machine-config.md)</translation>
    </message>
    <message>
        <source>cycle {1} cannot run with M128/FUNCTION TCPM active</source>
        <translation>Zyklus {1} kann nicht mit aktivem M128/FUNCTION TCPM laufen</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is an output of this run and cannot be read</source>
        <translation>&apos;{1}&apos; ist eine Ausgabe dieses Laufs und kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>TYPE OF DIMENSION</source>
        <translation>BEMASSUNGSART</translation>
    </message>
    <message>
        <source>RIDGE WIDTH</source>
        <translation>STEGBREITE</translation>
    </message>
    <message>
        <source>the contour subprogram {1} has no contour</source>
        <translation>das Kontur-Unterprogramm {1} enthält keine Kontur</translation>
    </message>
    <message>
        <source>Dwell time at the bottom</source>
        <translation>Verweilzeit unten</translation>
    </message>
    <message>
        <source>PECKING</source>
        <translation>TIEFBOHREN</translation>
    </message>
    <message>
        <source>TAPPING</source>
        <translation>GEWINDEBOHREN</translation>
    </message>
    <message>
        <source>Set-up clearance: tool tip at the start to surface</source>
        <translation>Sicherheitsabstand: Werkzeugspitze am Start bis Oberfläche</translation>
    </message>
    <message>
        <source>Depth from the surface (the sign gives the direction)</source>
        <translation>Tiefe ab Oberfläche (das Vorzeichen gibt die Richtung)</translation>
    </message>
    <message>
        <source>Feed rate</source>
        <translation>Vorschub</translation>
    </message>
    <message>
        <source>Feed rate for plunging (none: the milling feed)</source>
        <translation>Vorschub Zustellen (keiner: der Fräsvorschub)</translation>
    </message>
    <message>
        <source>Direction: DR+ counterclockwise, DR- clockwise</source>
        <translation>Richtung: DR+ Gegenuhrzeigersinn, DR- Uhrzeigersinn</translation>
    </message>
    <message>
        <source>First side length (parallel to the first axis)</source>
        <translation>1. Seitenlänge (parallel zur ersten Achse)</translation>
    </message>
    <message>
        <source>Pocket radius</source>
        <translation>Taschenradius</translation>
    </message>
    <message>
        <source>cycle {1} has no sub-block {1}.{2}</source>
        <translation>Zyklus {1} hat keinen Unterblock {1}.{2}</translation>
    </message>
    <message>
        <source>cycle {1}: the tool axis must be perpendicular to the axis of rotary table {2} (tilt the table or the head first, e.g. with PLANE)</source>
        <translation>Zyklus {1}: Die Werkzeugachse muss senkrecht zur Achse des Rundtischs {2} stehen (zuerst den Tisch oder den Kopf schwenken, z. B. mit PLANE)</translation>
    </message>
    <message>
        <source>PLANE AXIAL: {1} is not a rotary axis of the kinematics of this machine</source>
        <translation>PLANE AXIAL: {1} ist keine Drehachse der Kinematik dieser Maschine</translation>
    </message>
    <message>
        <source>TCPM needs the rotary axes described in the machine file ([kinematics], e.g. --machine mill5)</source>
        <translation>TCPM benötigt die in der Maschinendatei beschriebenen Drehachsen ([kinematics], z. B. --machine mill5)</translation>
    </message>
    <message>
        <source>How the rotary axes are built: none, one rotary table, a table on a tilting table, a swivel head and a table, or a fork head</source>
        <translation>Aufbau der Drehachsen: keine, ein Rundtisch, ein Tisch auf einem Schwenktisch, ein Schwenkkopf und ein Tisch oder ein Gabelkopf</translation>
    </message>
    <message>
        <source>The tilting rotary axis (SEQ+/SEQ- choose its sign)</source>
        <translation>Die schwenkende Drehachse (SEQ+/SEQ- wählen ihr Vorzeichen)</translation>
    </message>
    <message>
        <source>The second rotary axis: the table on the tilting table, the table of a head-table machine, the head axis carrying the fork</source>
        <translation>Die zweite Drehachse: der Tisch auf dem Schwenktisch, der Tisch einer Kopf-Tisch-Maschine, die Kopfachse, die die Gabel trägt</translation>
    </message>
    <message>
        <source>Head: X of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Kopf: X des Drehpunkts des Kopfs ab der Spindelnase, Kopf auf 0; head_pivot = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Head: Y of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Kopf: Y des Drehpunkts des Kopfs ab der Spindelnase, Kopf auf 0; head_pivot = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Head: Z of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Kopf: Z des Drehpunkts des Kopfs ab der Spindelnase, Kopf auf 0; head_pivot = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>kinematics.primary is the tilting axis: A or B, not C</source>
        <translation>kinematics.primary ist die Schwenkachse: A oder B, nicht C</translation>
    </message>
    <message>
        <source>FK: {1} is not an axis of the working plane</source>
        <translation>FK: {1} ist keine Achse der Bearbeitungsebene</translation>
    </message>
    <message>
        <source>G53 in a profile needs a G00 or G01 point in X, Z</source>
        <translation>G53 in einer Kontur braucht einen G00- oder G01-Punkt in X, Z</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: it rises {3}° from the passes and the cutting angle CUTA allows {4}°</source>
        <translation>Werkzeug T{1} erreicht die Kontur in Zeile {2} nicht: sie steigt {3}° gegen die Schnitte an und der Schneidenwinkel CUTA erlaubt {4}°</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: it descends {3}° into the material and CUTA + NOSEA leave {4}°</source>
        <translation>Werkzeug T{1} erreicht die Kontur in Zeile {2} nicht: sie fällt {3}° ins Material ab und CUTA + NOSEA lassen {4}°</translation>
    </message>
    <message>
        <source>Exact radius of the calibration sphere</source>
        <translation>Exakter Radius der Kalibrierkugel</translation>
    </message>
    <message>
        <source>Calibrate the length too: 0 no, 1 yes</source>
        <translation>Auch die Länge kalibrieren: 0 nein, 1 ja</translation>
    </message>
    <message>
        <source>Datum for the length: height of the sphere&apos;s centre</source>
        <translation>Bezugspunkt für die Länge: Höhe des Kugelmittelpunkts</translation>
    </message>
    <message>
        <source>Number of points for the 3D calibration (0: none)</source>
        <translation>Anzahl Punkte für die 3D-Kalibrierung (0: keine)</translation>
    </message>
    <message>
        <source>cycle {1}: the 3D calibration (Q455 &gt; 0, option 92) is not available; set Q455 = 0</source>
        <translation>Zyklus {1}: die 3D-Kalibrierung (Q455 &gt; 0, Option 92) ist nicht verfügbar; Q455 = 0 setzen</translation>
    </message>
    <message>
        <source>CALIBRATE TS ON SPHERE</source>
        <translation>TS AN KUGEL KALIBRIEREN</translation>
    </message>
    <message>
        <source>Result parameter</source>
        <translation>Ergebnisparameter</translation>
    </message>
    <message>
        <source>Probing angle</source>
        <translation>Antastwinkel</translation>
    </message>
    <message>
        <source>Maximum measuring path</source>
        <translation>Maximaler Messweg</translation>
    </message>
    <message>
        <source>Measuring feed</source>
        <translation>Messvorschub</translation>
    </message>
    <message>
        <source>Maximum retraction path</source>
        <translation>Maximaler Rückzugsweg</translation>
    </message>
    <message>
        <source>Reference system: 0 active, 1 machine</source>
        <translation>Bezugssystem: 0 aktiv, 1 Maschine</translation>
    </message>
    <message>
        <source>Error mode: 0 error if deflected at the start, 1 status -1</source>
        <translation>Fehlermodus: 0 Fehler, wenn beim Start ausgelenkt, 1 Status -1</translation>
    </message>
    <message>
        <source>{1}.{2}: the probing axis X, Y or Z expected</source>
        <translation>{1}.{2}: Antastachse X, Y oder Z erwartet</translation>
    </message>
    <message>
        <source>{1}.{2}: the probing direction IX, IY, IZ is zero</source>
        <translation>{1}.{2}: die Antastrichtung IX, IY, IZ ist null</translation>
    </message>
    <message>
        <source>G55: the probing axis with its direction (X-, Y+ ...) expected</source>
        <translation>G55: Antastachse mit Richtung (X-, Y+ ...) erwartet</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): X of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Kalibrierkugel (Zyklus 460): X ihres Mittelpunkts im programmierten Rahmen des Rohteils; centre = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): Y of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Kalibrierkugel (Zyklus 460): Y ihres Mittelpunkts im programmierten Rahmen des Rohteils; centre = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): Z of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Kalibrierkugel (Zyklus 460): Z ihres Mittelpunkts im programmierten Rahmen des Rohteils; centre = [x, y, z] schreiben</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): its exact radius; 0: none</source>
        <translation>Kalibrierkugel (Zyklus 460): ihr exakter Radius; 0: keine</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: the arc&apos;s radius {3} is smaller than the nose radius {4}</source>
        <translation>Werkzeug T{1} erreicht die Kontur in Zeile {2} nicht: der Bogenradius {3} ist kleiner als der Schneidenradius {4}</translation>
    </message>
    <message>
        <source>a label number from 1 to 65535 or a name expected</source>
        <translation>Label-Nummer von 1 bis 65535 oder ein Name erwartet</translation>
    </message>
    <message>
        <source>cycle {1}: {2} expected in {1}.{3}</source>
        <translation>Zyklus {1}: {2} erwartet in {1}.{3}</translation>
    </message>
    <message>
        <source>FUNCTION MODE MILL: the machine file sets the kinematics; &apos;{1}&apos; cannot be selected</source>
        <translation>FUNCTION MODE MILL: die Kinematik legt die Maschinendatei fest; &apos;{1}&apos; kann nicht gewählt werden</translation>
    </message>
    <message>
        <source>FUNCTION MODE TURN: this machine has no turning mode</source>
        <translation>FUNCTION MODE TURN: diese Maschine hat keinen Drehbetrieb</translation>
    </message>
    <message>
        <source>FUNCTION MODE: MILL or TURN expected</source>
        <translation>FUNCTION MODE: MILL oder TURN erwartet</translation>
    </message>
    <message>
        <source>M120 LA: a whole number of blocks from 0 to 99</source>
        <translation>M120 LA: eine ganze Anzahl Sätze von 0 bis 99</translation>
    </message>
    <message>
        <source>CALL SELECTED PGM: no program was selected with SEL PGM</source>
        <translation>CALL SELECTED PGM: mit SEL PGM wurde kein Programm gewählt</translation>
    </message>
    <message>
        <source>cycle {1}: no room for the helical plunge, and the reciprocating plunge needs the tool&apos;s LCUTS (pre-drill with cycle 21 or use a centre-cutting tool)</source>
        <translation>Zyklus {1}: kein Platz für das helixförmige Eintauchen, und das pendelnde Eintauchen braucht die LCUTS des Werkzeugs (mit Zyklus 21 vorbohren oder ein über Mitte schneidendes Werkzeug verwenden)</translation>
    </message>
    <message>
        <source>Axis of the first side length: 0 main axis, 1 secondary axis</source>
        <translation>Achse der 1. Seitenlänge: 0 Hauptachse, 1 Nebenachse</translation>
    </message>
    <message>
        <source>cycle {1}: the tool diameter must be at least half the slot width</source>
        <translation>Zyklus {1}: der Werkzeugdurchmesser muss mindestens die halbe Nutbreite sein</translation>
    </message>
    <message>
        <source>cycle {1}: the slot is shorter than it is wide</source>
        <translation>Zyklus {1}: die Nut ist kürzer als breit</translation>
    </message>
    <message>
        <source>manual probing: call the touch probe with TOOL CALL first (MDI)</source>
        <translation>manuelles Antasten: zuerst das Tastsystem mit TOOL CALL aufrufen (MDI)</translation>
    </message>
    <message>
        <source>manual probing: tool {1} is not in TOOL.T</source>
        <translation>manuelles Antasten: Werkzeug {1} steht nicht in TOOL.T</translation>
    </message>
    <message>
        <source>manual probing: probe {1} is not in tchprobe.tp</source>
        <translation>manuelles Antasten: Tastsystem {1} steht nicht in tchprobe.tp</translation>
    </message>
    <message>
        <source>In ISO programs cycle %1 takes only %2: leave the other fields empty</source>
        <translation>In ISO-Programmen nimmt Zyklus %1 nur %2 auf: die übrigen Felder leer lassen</translation>
    </message>
    <message>
        <source>the rotary axes turn too far in this block to keep the tool tip on the path; split the block</source>
        <translation>die Drehachsen drehen sich in diesem Satz zu weit, um die Werkzeugspitze auf der Bahn zu halten; den Satz aufteilen</translation>
    </message>
    <message>
        <source>M94 {1}: the machine has no rotary axis {1}</source>
        <translation>M94 {1}: die Maschine hat keine Drehachse {1}</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest X, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Simuliertes Rohteil eines Programms ohne BLK FORM: sein kleinstes X, Werkstückkoordinaten des Presets der Maschinendatei; schreiben Sie min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest Y, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Simuliertes Rohteil eines Programms ohne BLK FORM: sein kleinstes Y, Werkstückkoordinaten des Presets der Maschinendatei; schreiben Sie min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest Z, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Simuliertes Rohteil eines Programms ohne BLK FORM: sein kleinstes Z, Werkstückkoordinaten des Presets der Maschinendatei; schreiben Sie min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest X, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Simuliertes Rohteil eines Programms ohne BLK FORM: sein größtes X, Werkstückkoordinaten des Presets der Maschinendatei; schreiben Sie max = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest Y, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Simuliertes Rohteil eines Programms ohne BLK FORM: sein größtes Y, Werkstückkoordinaten des Presets der Maschinendatei; schreiben Sie max = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest Z, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Simuliertes Rohteil eines Programms ohne BLK FORM: sein größtes Z, Werkstückkoordinaten des Presets der Maschinendatei; schreiben Sie max = [x, y, z]</translation>
    </message>
    <message>
        <source>tool length touch-off: no tool in the spindle</source>
        <translation>Werkzeuglänge ankratzen: kein Werkzeug in der Spindel</translation>
    </message>
    <message>
        <source>tool length touch-off: tool {1} is not in TOOL.T</source>
        <translation>Werkzeuglänge ankratzen: Werkzeug {1} steht nicht in TOOL.T</translation>
    </message>
    <message>
        <source>Positioning: TURN, MOVE (DIST) or STAY</source>
        <translation>Positionieren: TURN, MOVE (DIST) oder STAY</translation>
    </message>
    <message>
        <source>Retract along the tool axis first: MAX or mm</source>
        <translation>Zuerst in Werkzeugachse freifahren: MAX oder mm</translation>
    </message>
    <message>
        <source>MOVE: distance of the tool tip from the centre of rotation</source>
        <translation>MOVE: Abstand der Werkzeugspitze vom Drehpunkt</translation>
    </message>
    <message>
        <source>Feed rate of the positioning, or FMAX</source>
        <translation>Vorschub der Positionierung oder FMAX</translation>
    </message>
    <message>
        <source>Solution: SEQ+ or SEQ- (empty: the machine&apos;s)</source>
        <translation>Lösung: SEQ+ oder SEQ- (leer: die der Maschine)</translation>
    </message>
    <message>
        <source>Transformation: COORD ROT or TABLE ROT</source>
        <translation>Transformation: COORD ROT oder TABLE ROT</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not allowed here</source>
        <translation>%1: „%2“ ist hier nicht erlaubt</translation>
    </message>
    <message>
        <source>Spatial angle A [°]</source>
        <translation>Raumwinkel A [°]</translation>
    </message>
    <message>
        <source>Spatial angle B [°]</source>
        <translation>Raumwinkel B [°]</translation>
    </message>
    <message>
        <source>Spatial angle C [°]</source>
        <translation>Raumwinkel C [°]</translation>
    </message>
    <message>
        <source>Projected angle in the principal plane [°]</source>
        <translation>Projektionswinkel in der Hauptebene [°]</translation>
    </message>
    <message>
        <source>Projected angle in the minor plane [°]</source>
        <translation>Projektionswinkel in der Nebenebene [°]</translation>
    </message>
    <message>
        <source>Rotation in the tilted plane [°]</source>
        <translation>Drehung in der geschwenkten Ebene [°]</translation>
    </message>
    <message>
        <source>Precession angle [°]</source>
        <translation>Präzessionswinkel [°]</translation>
    </message>
    <message>
        <source>Nutation angle [°]</source>
        <translation>Nutationswinkel [°]</translation>
    </message>
    <message>
        <source>Rotation angle [°]</source>
        <translation>Drehwinkel [°]</translation>
    </message>
    <message>
        <source>Base vector (X direction)</source>
        <translation>Basisvektor (X-Richtung)</translation>
    </message>
    <message>
        <source>Normal vector</source>
        <translation>Normalenvektor</translation>
    </message>
    <message>
        <source>First point (origin of X)</source>
        <translation>Erster Punkt (Ursprung von X)</translation>
    </message>
    <message>
        <source>Second point (on the X axis)</source>
        <translation>Zweiter Punkt (auf der X-Achse)</translation>
    </message>
    <message>
        <source>Third point (in the plane)</source>
        <translation>Dritter Punkt (in der Ebene)</translation>
    </message>
    <message>
        <source>Axis of the incremental spatial angle</source>
        <translation>Achse des inkrementalen Raumwinkels</translation>
    </message>
    <message>
        <source>Incremental angle [°]</source>
        <translation>Inkrementaler Winkel [°]</translation>
    </message>
    <message>
        <source>Axis angle [°] (empty: not moved)</source>
        <translation>Achswinkel [°] (leer: nicht verfahren)</translation>
    </message>
    <message>
        <source>Feed rate at the tool tip</source>
        <translation>Vorschub an der Werkzeugspitze</translation>
    </message>
    <message>
        <source>Rotary axes: machine positions</source>
        <translation>Drehachsen: Maschinenpositionen</translation>
    </message>
    <message>
        <source>Path: the axes interpolate linearly</source>
        <translation>Bahn: die Achsen interpolieren linear</translation>
    </message>
    <message>
        <source>Reference point: the tool tip</source>
        <translation>Bezugspunkt: die Werkzeugspitze</translation>
    </message>
    <message>
        <source>Feed rate of the compensating moves</source>
        <translation>Vorschub der Ausgleichsbewegungen</translation>
    </message>
    <message>
        <source>Program name, e.g. PART or TNC:\DIR\PART.H</source>
        <translation>Programmname, z. B. PART oder TNC:\DIR\PART.H</translation>
    </message>
    <message>
        <source>PLANE AXIAL: enter the angle of A, B or C</source>
        <translation>PLANE AXIAL: den Winkel von A, B oder C eingeben</translation>
    </message>
    <message>
        <source>STAY moves nothing: leave MB, DIST and F empty</source>
        <translation>STAY verfährt nichts: MB, DIST und F leer lassen</translation>
    </message>
    <message>
        <source>DIST belongs to MOVE</source>
        <translation>DIST gehört zu MOVE</translation>
    </message>
    <message>
        <source>stopped after {1} blocks: endless loop? (--max-blocks)</source>
        <translation>nach {1} Sätzen angehalten: Endlosschleife? (--max-blocks)</translation>
    </message>
    <message>
        <source>LN needs all of NX NY NZ, and TX TY TZ all or none</source>
        <translation>LN braucht NX NY NZ vollständig und TX TY TZ ganz oder gar nicht</translation>
    </message>
    <message>
        <source>FUNCTION TCPM: only F TCP|CONT, AXIS POS|SPAT, PATHCTRL AXIS|VECTOR and REFPNT TIP-TIP are supported, not &apos;{1}&apos;</source>
        <translation>FUNCTION TCPM: nur F TCP|CONT, AXIS POS|SPAT, PATHCTRL AXIS|VECTOR und REFPNT TIP-TIP werden unterstützt, nicht &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>LN compensates along the surface normal: switch the radius compensation off (R0) first</source>
        <translation>LN korrigiert entlang der Flächennormalen: zuerst die Radiuskorrektur ausschalten (R0)</translation>
    </message>
    <message>
        <source>LN: a vector NX NY NZ or TX TY TZ has no length</source>
        <translation>LN: ein Vektor NX NY NZ oder TX TY TZ hat keine Länge</translation>
    </message>
    <message>
        <source>LN: the rotary axes of this machine cannot turn the tool along TX TY TZ</source>
        <translation>LN: die Drehachsen dieser Maschine können das Werkzeug nicht entlang TX TY TZ drehen</translation>
    </message>
    <message>
        <source>with TCPM on the program positions the rotary axes: tilt with STAY, or switch TCPM off first</source>
        <translation>mit aktivem TCPM positioniert das Programm die Drehachsen: mit STAY schwenken oder zuerst TCPM ausschalten</translation>
    </message>
    <message>
        <source>AXIS SPAT: the rotary axes of this machine cannot turn the tool to the spatial angles A {1} B {2} C {3}</source>
        <translation>AXIS SPAT: die Drehachsen dieser Maschine können das Werkzeug nicht auf die Raumwinkel A {1} B {2} C {3} drehen</translation>
    </message>
    <message>
        <source>the arc&apos;s radius {1} is smaller than the tool nose radius {2}: the nose cannot follow it</source>
        <translation>der Bogenradius {1} ist kleiner als der Schneidenradius {2} des Werkzeugs: die Schneide kann ihm nicht folgen</translation>
    </message>
    <message>
        <source>Pattern repeat cycle</source>
        <translation>Zyklus Konturfolge</translation>
    </message>
    <message>
        <source>Stock removal cycle along X</source>
        <translation>Schruppzyklus entlang X</translation>
    </message>
    <message>
        <source>Stock removal cycle along Z</source>
        <translation>Schruppzyklus entlang Z</translation>
    </message>
    <message>
        <source>Turning cycle, straight sections</source>
        <translation>Längsdrehzyklus, gerade Abschnitte</translation>
    </message>
    <message>
        <source>Facing cycle, straight sections</source>
        <translation>Plandrehzyklus, gerade Abschnitte</translation>
    </message>
    <message>
        <source>Axial drilling / tapping cycle</source>
        <translation>Zyklus axiales Bohren / Gewindebohren</translation>
    </message>
    <message>
        <source>Turning cycle, curved sections</source>
        <translation>Längsdrehzyklus, Bogenabschnitte</translation>
    </message>
    <message>
        <source>Facing cycle, curved sections</source>
        <translation>Plandrehzyklus, Bogenabschnitte</translation>
    </message>
    <message>
        <source>Longitudinal threading cycle</source>
        <translation>Zyklus Längsgewinde</translation>
    </message>
    <message>
        <source>Face threading cycle</source>
        <translation>Zyklus Plangewinde</translation>
    </message>
    <message>
        <source>Grooving cycle along X</source>
        <translation>Einstechzyklus entlang X</translation>
    </message>
    <message>
        <source>the program check stopped after {1} blocks: endless loop?</source>
        <translation>die Programmprüfung hat nach {1} Sätzen angehalten: Endlosschleife?</translation>
    </message>
    <message>
        <source>Grooving cycle along Z</source>
        <translation>Einstechzyklus entlang Z</translation>
    </message>
    <message>
        <source>tapping and thread cutting follow the spindle along the tool axis: switch TCPM off first (M129 or FUNCTION RESET TCPM)</source>
        <translation>Gewindebohren und Gewindeschneiden folgen der Spindel entlang der Werkzeugachse: zuerst TCPM ausschalten (M129 oder FUNCTION RESET TCPM)</translation>
    </message>
    <message>
        <source>cannot write the calibration log {1}: {2}</source>
        <translation>das Kalibrierprotokoll {1} kann nicht geschrieben werden: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the touch-probe table: {2}</source>
        <translation>Tastsystemzyklus {1}: die Tastsystemtabelle kann nicht geschrieben werden: {2}</translation>
    </message>
    <message>
        <source>{1} must be an array of two numbers [x, y] within +-10 mm, not {2}</source>
        <translation>{1} muss ein Feld aus zwei Zahlen [x, y] innerhalb von +-10 mm sein, nicht {2}</translation>
    </message>
    <message>
        <source>probe {1} is not in the touch-probe table</source>
        <translation>Tastsystem {1} ist nicht in der Tastsystemtabelle</translation>
    </message>
    <message>
        <source>cannot add a column &quot;{1}&quot;</source>
        <translation>die Spalte &quot;{1}&quot; kann nicht hinzugefügt werden</translation>
    </message>
    <message>
        <source>{1} is not allowed beside the polar coordinates PR/PA (only the tool axis may be programmed)</source>
        <translation>{1} ist neben den Polarkoordinaten PR/PA nicht erlaubt (nur die Werkzeugachse darf programmiert werden)</translation>
    </message>
    <message>
        <source>QR{1} = &apos;{2}&apos; is not a finite number</source>
        <translation>QR{1} = &apos;{2}&apos; ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>column {1} needs a whole number from 0 to {2}, not &quot;{3}&quot;</source>
        <translation>Spalte {1} braucht eine ganze Zahl von 0 bis {2}, nicht &quot;{3}&quot;</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the probe {2} cannot be turned to each probing direction (angle tracking of cycle 441, Q399 = 1)</source>
        <translation>Tastsystemzyklus {1}: das Tastsystem {2} kann nicht in jede Antastrichtung gedreht werden (Winkelnachführung von Zyklus 441, Q399 = 1)</translation>
    </message>
    <message>
        <source>column TYPE: unknown probe &quot;{1}&quot; (known: {2})</source>
        <translation>Spalte TYPE: unbekanntes Tastsystem &quot;{1}&quot; (bekannt: {2})</translation>
    </message>
    <message>
        <source>TRACK ON needs a probe the spindle can turn to any angle; {1} cannot be</source>
        <translation>TRACK ON braucht ein Tastsystem, das die Spindel in jeden Winkel drehen kann; {1} kann das nicht</translation>
    </message>
    <message>
        <source>LN: the tool is larger than the CAM system&apos;s (DR {1}, DR2 {2} from the tool table and TOOL CALL): program M107 to permit positive oversizes</source>
        <translation>LN: Das Werkzeug ist größer als das des CAM-Systems (DR {1}, DR2 {2} aus Werkzeugtabelle und TOOL CALL): M107 programmieren, um positive Aufmaße zuzulassen</translation>
    </message>
    <message>
        <source>LN: the corner radius R2+DR2 {1} must lie between 0 (end mill) and the radius R+DR {2} (ball cutter)</source>
        <translation>LN: Der Eckenradius R2+DR2 {1} muss zwischen 0 (Schaftfräser) und dem Radius R+DR {2} (Radiusfräser) liegen</translation>
    </message>
    <message>
        <source>LN: the rotary axes of this machine cannot turn the tool along the surface normal NX NY NZ</source>
        <translation>LN: Die Drehachsen dieser Maschine können das Werkzeug nicht entlang der Flächennormalen NX NY NZ drehen</translation>
    </message>
    <message>
        <source>LN is the conversational straight line with 3D tool compensation; in ISO write G01 X Y Z NX NY NZ [TX TY TZ]</source>
        <translation>LN ist die Klartext-Gerade mit 3D-Werkzeugkorrektur; in ISO G01 X Y Z NX NY NZ [TX TY TZ] schreiben</translation>
    </message>
    <message>
        <source>surface vectors NX NY NZ TX TY TZ belong to a straight line G00/G01</source>
        <translation>Flächenvektoren NX NY NZ TX TY TZ gehören zu einer Geraden G00/G01</translation>
    </message>
    <message>
        <source>SL cycles (21-25, 275, 276) end back at the position before the cycle (the TNC&apos;s posAfterContPocket = PosBeforeMachining); false: at the clearance height Q7, the tool axis only (ToolAxClearanceHeight)</source>
        <translation>SL-Zyklen (21-25, 275, 276) enden wieder an der Position vor dem Zyklus (posAfterContPocket = PosBeforeMachining der TNC); false: auf der sicheren Höhe Q7, nur in der Werkzeugachse (ToolAxClearanceHeight)</translation>
    </message>
    <message>
        <source>the simulated part holds the cuts of the first {1} tool moves only: later moves removed no material</source>
        <translation>das simulierte Werkstück enthält nur die Schnitte der ersten {1} Werkzeugbewegungen: spätere Bewegungen haben kein Material abgetragen</translation>
    </message>
    <message>
        <source>Allowance in the 1st axis left by roughing</source>
        <translation>Aufmaß in der 1. Achse, vom Schruppen gelassen</translation>
    </message>
    <message>
        <source>POCKET FINISHING</source>
        <translation>TASCHE SCHLICHTEN</translation>
    </message>
    <message>
        <source>STUD FINISHING</source>
        <translation>ZAPFEN SCHLICHTEN</translation>
    </message>
    <message>
        <source>CIRCULAR POCKET FINISHING</source>
        <translation>KREISTASCHE SCHLICHTEN</translation>
    </message>
    <message>
        <source>CIRCULAR STUD FINISHING</source>
        <translation>KREISZAPFEN SCHLICHTEN</translation>
    </message>
    <message>
        <source>Number of cuts</source>
        <translation>Anzahl Schnitte</translation>
    </message>
    <message>
        <source>Feed rate to the starting point in the tool axis</source>
        <translation>Vorschub zum Startpunkt in der Werkzeugachse</translation>
    </message>
    <message>
        <source>Feed rate for stepover (FMAX: rapid)</source>
        <translation>Vorschub für den Querversatz (FMAX: Eilgang)</translation>
    </message>
    <message>
        <source>MULTIPASS MILLING</source>
        <translation>ABZEILEN</translation>
    </message>
    <message>
        <source>SLOT RECIP. PLNG.</source>
        <translation>NUT PENDELND</translation>
    </message>
    <message>
        <source>Starting point in the 3rd axis</source>
        <translation>Startpunkt in der 3. Achse</translation>
    </message>
    <message>
        <source>2nd point in the 1st axis</source>
        <translation>2. Punkt in der 1. Achse</translation>
    </message>
    <message>
        <source>2nd point in the 2nd axis</source>
        <translation>2. Punkt in der 2. Achse</translation>
    </message>
    <message>
        <source>2nd point in the 3rd axis</source>
        <translation>2. Punkt in der 3. Achse</translation>
    </message>
    <message>
        <source>3rd point in the 1st axis</source>
        <translation>3. Punkt in der 1. Achse</translation>
    </message>
    <message>
        <source>3rd point in the 2nd axis</source>
        <translation>3. Punkt in der 2. Achse</translation>
    </message>
    <message>
        <source>3rd point in the 3rd axis</source>
        <translation>3. Punkt in der 3. Achse</translation>
    </message>
    <message>
        <source>4th point in the 1st axis</source>
        <translation>4. Punkt in der 1. Achse</translation>
    </message>
    <message>
        <source>4th point in the 2nd axis</source>
        <translation>4. Punkt in der 2. Achse</translation>
    </message>
    <message>
        <source>4th point in the 3rd axis</source>
        <translation>4. Punkt in der 3. Achse</translation>
    </message>
    <message>
        <source>RULED SURFACE</source>
        <translation>REGELFLÄCHE</translation>
    </message>
    <message>
        <source>cycle {1}: the two points of a measured line coincide</source>
        <translation>Zyklus {1}: die beiden Punkte einer gemessenen Geraden fallen zusammen</translation>
    </message>
    <message>
        <source>mm (radius)</source>
        <translation>mm (Radius)</translation>
    </message>
    <message>
        <source>collision: a rapid move runs into the material of the blank</source>
        <translation>Kollision: eine Eilgangbewegung fährt in das Material des Rohteils</translation>
    </message>
    <message>
        <source>ready</source>
        <comment>machine state</comment>
        <translation>bereit</translation>
    </message>
    <message>
        <source>running</source>
        <comment>machine state</comment>
        <translation>läuft</translation>
    </message>
    <message>
        <source>feed hold</source>
        <comment>machine state</comment>
        <translation>Vorschub-Halt</translation>
    </message>
    <message>
        <source>stopped</source>
        <comment>machine state</comment>
        <translation>gestoppt</translation>
    </message>
    <message>
        <source>jogging</source>
        <comment>machine state</comment>
        <translation>Tippbetrieb</translation>
    </message>
    <message>
        <source>homing</source>
        <comment>machine state</comment>
        <translation>Referenzfahren</translation>
    </message>
    <message>
        <source>stopping</source>
        <comment>machine state</comment>
        <translation>wird angehalten</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <comment>machine state</comment>
        <translation>Not-Aus</translation>
    </message>
    <message>
        <source>fault</source>
        <comment>machine state</comment>
        <translation>Störung</translation>
    </message>
    <message>
        <source>no machine</source>
        <comment>machine state</comment>
        <translation>keine Maschine</translation>
    </message>
    <message>
        <source>Block {1}: the machine has no axis {2}.</source>
        <translation>Satz {1}: die Maschine hat keine Achse {2}.</translation>
    </message>
    <message>
        <source>Block {1}: the move would take axis {2} to {3} (machine coordinates), beyond its soft limit {4}; the program is not run past this block.</source>
        <translation>Satz {1}: die Bewegung würde die Achse {2} auf {3} (Maschinenkoordinaten) fahren, jenseits ihres Software-Endschalters {4}; das Programm läuft nicht über diesen Satz hinaus.</translation>
    </message>
    <message>
        <source>Block {1}: feed per revolution with the spindle stopped.</source>
        <translation>Satz {1}: Vorschub pro Umdrehung bei stehender Spindel.</translation>
    </message>
    <message>
        <source>Block {1}: feed move without a feed rate.</source>
        <translation>Satz {1}: Vorschubbewegung ohne Vorschub.</translation>
    </message>
    <message>
        <source>Block {1}: {2} = {3} is outside the range of the control; the program is not run past this block.</source>
        <translation>Satz {1}: {2} = {3} liegt außerhalb des Bereichs der Steuerung; das Programm läuft nicht über diesen Satz hinaus.</translation>
    </message>
    <message>
        <source>Block {1}: the arc&apos;s end point is {2} mm off its circle.</source>
        <translation>Satz {1}: der Endpunkt des Kreises liegt {2} mm neben seiner Kreisbahn.</translation>
    </message>
    <message>
        <source>Block {1}: threads with a variable lead (G34) cannot be executed yet.</source>
        <translation>Satz {1}: Gewinde mit veränderlicher Steigung (G34) können noch nicht ausgeführt werden.</translation>
    </message>
    <message>
        <source>Block {1}: spindle-synchronised move without a lead or a spindle speed.</source>
        <translation>Satz {1}: spindelsynchrone Bewegung ohne Steigung oder Spindeldrehzahl.</translation>
    </message>
    <message>
        <source>Cannot write the samples file {1}.</source>
        <translation>Die Abtastdatei {1} kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Motion error {1} at line {2}.</source>
        <translation>Bewegungsfehler {1} in Zeile {2}.</translation>
    </message>
    <message>
        <source>Emergency stop at {1} s after the start (the button was pressed): every axis and the spindle were stopped and the program was aborted.</source>
        <translation>Not-Aus {1} s nach dem Start (die Taste wurde gedrückt): alle Achsen und die Spindel wurden angehalten und das Programm abgebrochen.</translation>
    </message>
    <message>
        <source>The simulation reached its limit of {1} s of simulated time before the program&apos;s motion ended: the run stops here.</source>
        <translation>Die Simulation hat ihre Grenze von {1} s simulierter Zeit erreicht, bevor die Bewegung des Programms endete: der Lauf endet hier.</translation>
    </message>
    <message>
        <source>cycle {1}: a rotation measured in the ZX or YZ plane (Q1139 = {2}) turns about X or Y; only a basic rotation about the tool axis can be accepted (Q1121 = 0)</source>
        <translation>Zyklus {1}: eine in der Ebene ZX oder YZ gemessene Drehung (Q1139 = {2}) dreht um X oder Y; übernommen werden kann nur eine Grunddrehung um die Werkzeugachse (Q1121 = 0)</translation>
    </message>
    <message>
        <source>cycle {1}: Q{2} is given as an actual position, but neither edge is probed along that axis</source>
        <translation>Zyklus {1}: Q{2} ist als Istposition angegeben, aber keine der beiden Kanten wird entlang dieser Achse angetastet</translation>
    </message>
    <message>
        <source>Direction of the extrusion: 1 main axis, 2 secondary, 3 tool axis</source>
        <translation>Richtung der Extrusion: 1 Hauptachse, 2 Nebenachse, 3 Werkzeugachse</translation>
    </message>
    <message>
        <source>Length of the extrusion (incremental, the sign gives the way)</source>
        <translation>Länge der Extrusion (inkremental, das Vorzeichen gibt die Richtung)</translation>
    </message>
    <message>
        <source>Number of further touch points along the extrusion</source>
        <translation>Anzahl weiterer Antastpunkte entlang der Extrusion</translation>
    </message>
    <message>
        <source>Extrusion active for: 0 the next 14xx cycle, 1 all following</source>
        <translation>Extrusion wirksam für: 0 den nächsten 14xx-Zyklus, 1 alle folgenden</translation>
    </message>
    <message>
        <source>PROBING EXTRUSION</source>
        <translation>ANTASTEN EXTRUSION</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) takes no actual position (nominal@actual is for the nominal positions of a 14xx cycle)</source>
        <translation>{1}: Parameter {2} ({3}) nimmt keine Istposition an (Soll@Ist gilt für die Sollpositionen eines 14xx-Zyklus)</translation>
    </message>
    <message>
        <source>the probe stopped {1} mm beyond its touch point, more than its stylus can be deflected ({2} mm): lower the probing feed F in tchprobe.tp</source>
        <translation>der Taster hielt {1} mm hinter seinem Antastpunkt an, weiter als sein Taststift ausgelenkt werden kann ({2} mm): den Antastvorschub F in tchprobe.tp verringern</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the simulated tools: {2}</source>
        <translation>Tastsystemzyklus {1}: die simulierten Werkzeuge können nicht geschrieben werden: {2}</translation>
    </message>
    <message>
        <source>cycle 1416 (semi-automatic mode): position the probe before touch point {1} of edge {2}, within {3} mm of the edge, probing at {4} degrees in the plane; then NC start</source>
        <translation>Zyklus 1416 (Halbautomatik): das Tastsystem vor Antastpunkt {1} der Kante {2} positionieren, höchstens {3} mm von der Kante, Antastrichtung {4} Grad in der Ebene; dann NC-Start</translation>
    </message>
    <message>
        <source>cycle {1}: the semi-automatic mode (&apos;?&apos;) cannot repeat its touches along an extrusion (cycle 1493)</source>
        <translation>Zyklus {1}: der halbautomatische Modus (&apos;?&apos;) kann seine Antastungen nicht entlang einer Extrusion (Zyklus 1493) wiederholen</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) cannot be unknown (&apos;?&apos; is for the nominal positions of a 14xx cycle)</source>
        <translation>{1}: Parameter {2} ({3}) kann nicht unbekannt sein (&apos;?&apos; gilt für die Sollpositionen eines 14xx-Zyklus)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::BlockName</name>
    <message>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>Block %1</source>
        <translation>Satz %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::BlockPrompt</name>
    <message>
        <source>Line</source>
        <translation>Zeile</translation>
    </message>
    <message>
        <source>Block number</source>
        <translation>Satznummer</translation>
    </message>
    <message>
        <source>Block number N</source>
        <translation>Satznummer N</translation>
    </message>
    <message>
        <source>The program has no block %1</source>
        <translation>Das Programm hat keinen Satz %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineRows</name>
    <message>
        <source>Increment
continuous</source>
        <translation>Schrittmaß
aus</translation>
    </message>
    <message>
        <source>Increment
%1 mm</source>
        <translation>Schrittmaß
%1 mm</translation>
    </message>
    <message>
        <source>Home
all</source>
        <translation>Alle
referenzieren</translation>
    </message>
    <message>
        <source>Spindle
on</source>
        <translation>Spindel
ein</translation>
    </message>
    <message>
        <source>Spindle
off</source>
        <translation>Spindel
aus</translation>
    </message>
    <message>
        <source>NC
start</source>
        <translation>NC-
Start</translation>
    </message>
    <message>
        <source>NC stop
(feed hold)</source>
        <translation>NC-Stopp
(Vorschub-Halt)</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Start at
block</source>
        <translation>Satzvorlauf</translation>
    </message>
    <message>
        <source>Single block
on</source>
        <translation>Einzelsatz
ein</translation>
    </message>
    <message>
        <source>Single block
off</source>
        <translation>Einzelsatz
aus</translation>
    </message>
    <message>
        <source>Execute
block</source>
        <translation>Satz
ausführen</translation>
    </message>
    <message>
        <source>Set preset</source>
        <translation>Bezugspunkt setzen</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <source>Position of %1 at the current point</source>
        <translation>Position von %1 am aktuellen Punkt</translation>
    </message>
    <message>
        <source>Handwheel
axis %1</source>
        <translation>Handrad
Achse %1</translation>
    </message>
    <message>
        <source>Step
x%1</source>
        <translation>Schritt
x%1</translation>
    </message>
    <message>
        <source>Handwheel
-</source>
        <translation>Handrad
-</translation>
    </message>
    <message>
        <source>Handwheel
+</source>
        <translation>Handrad
+</translation>
    </message>
    <message>
        <source>Coolant
on</source>
        <translation>Kühlmittel
ein</translation>
    </message>
    <message>
        <source>Coolant
off</source>
        <translation>Kühlmittel
aus</translation>
    </message>
    <message>
        <source>Set
preset</source>
        <translation>Bezugspunkt
setzen</translation>
    </message>
    <message>
        <source>Spindle speed</source>
        <translation>Spindeldrehzahl</translation>
    </message>
    <message>
        <source>S in rpm (%1 to %2)</source>
        <translation>S in 1/min (%1 bis %2)</translation>
    </message>
    <message>
        <source>Probing: the touches give no result</source>
        <translation>Antasten: die Antastpunkte ergeben kein Ergebnis</translation>
    </message>
    <message>
        <source>Probing ROT</source>
        <translation>Antasten ROT</translation>
    </message>
    <message>
        <source>Basic rotation in degrees (OK writes it to the preset table)</source>
        <translation>Grunddrehung in Grad (OK schreibt sie in die Preset-Tabelle)</translation>
    </message>
    <message>
        <source>Probing CC: diameter %1 mm</source>
        <translation>Antasten CC: Durchmesser %1 mm</translation>
    </message>
    <message>
        <source>Probing</source>
        <translation>Antasten</translation>
    </message>
    <message>
        <source>Probed %1 = %2: the datum value there</source>
        <translation>Angetastet %1 = %2: Wert des Bezugspunkts dort</translation>
    </message>
    <message>
        <source>Probing
ROT</source>
        <translation>Antasten
ROT</translation>
    </message>
    <message>
        <source>Probing
POS</source>
        <translation>Antasten
POS</translation>
    </message>
    <message>
        <source>Probing
P</source>
        <translation>Antasten
P</translation>
    </message>
    <message>
        <source>Probing
CC</source>
        <translation>Antasten
CC</translation>
    </message>
    <message>
        <source>Direction
%1</source>
        <translation>Richtung
%1</translation>
    </message>
    <message>
        <source>Tool calibration</source>
        <translation>Werkzeugkalibrierung</translation>
    </message>
    <message>
        <source>Tool offset D</source>
        <translation>Werkzeugkorrektur D</translation>
    </message>
    <message>
        <source>Axis touched</source>
        <translation>Angetastete Achse</translation>
    </message>
    <message>
        <source>Position of %1 where the tool touches</source>
        <translation>Position von %1 an der Berührstelle des Werkzeugs</translation>
    </message>
    <message>
        <source>Tool
calibration</source>
        <translation>Werkzeug
kalibrieren</translation>
    </message>
    <message>
        <source>Touch %1
%2/%3</source>
        <translation>Tastpunkt %1
%2/%3</translation>
    </message>
    <message>
        <source>Tool length
touch-off</source>
        <translation>Werkzeuglänge
ankratzen</translation>
    </message>
    <message>
        <source>Tool length touch-off</source>
        <translation>Werkzeuglänge ankratzen</translation>
    </message>
    <message>
        <source>Z of the surface the tool touches</source>
        <translation>Z der Fläche, die das Werkzeug berührt</translation>
    </message>
    <message>
        <source>Probing PL: A %1 degrees, B %2 degrees</source>
        <translation>Antasten PL: A %1 Grad, B %2 Grad</translation>
    </message>
    <message>
        <source>Probing
PL</source>
        <translation>Antasten
PL</translation>
    </message>
    <message>
        <source>Diameter %1 at the current point</source>
        <translation>Durchmesser %1 am aktuellen Punkt</translation>
    </message>
    <message>
        <source>Diameter %1 where the tool touches</source>
        <translation>Durchmesser %1 an der Berührstelle des Werkzeugs</translation>
    </message>
</context>
<context>
    <name>kerf::ui::RenumberPrompt</name>
    <message>
        <source>Renumber blocks</source>
        <translation>Sätze neu nummerieren</translation>
    </message>
    <message>
        <source>First block number N</source>
        <translation>Erste Satznummer N</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schrittweite</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 names a label through a parameter, which could not follow it</source>
        <translation>Sätze nicht neu nummeriert: Zeile %1 nennt ein Label über einen Parameter, der ihm nicht folgen könnte</translation>
    </message>
    <message>
        <source>Blocks not renumbered: the profile of the cycle in line %1 would start or end at N%2; G66, G68 and G69 take labels of 4 digits</source>
        <translation>Sätze nicht neu nummeriert: die Kontur des Zyklus in Zeile %1 würde bei N%2 beginnen oder enden; G66, G68 und G69 nehmen 4-stellige Labels</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 would get N%2, beyond N99999999</source>
        <translation>Sätze nicht neu nummeriert: Zeile %1 bekäme N%2, über N99999999 hinaus</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 would get N%2, which line %3 carries already; the new line has no block number</source>
        <translation>Sätze nicht neu nummeriert: Zeile %1 bekäme N%2, das Zeile %3 schon trägt; die neue Zeile hat keine Satznummer</translation>
    </message>
</context>
</TS>
