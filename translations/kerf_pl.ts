<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pl_PL">
<context>
    <name>kerf::ui::CycleCatalogueDialog</name>
    <message>
        <source>There is no cycle %1</source>
        <translation>Nie ma cyklu %1</translation>
    </message>
    <message>
        <source>Cycle definition</source>
        <translation>Definicja cyklu</translation>
    </message>
    <message>
        <source>Cycle number</source>
        <translation>Numer cyklu</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
</context>
<context>
    <name>kerf::ui::CycleDialog</name>
    <message>
        <source>Cycle definition</source>
        <translation>Definicja cyklu</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FagorCycleDialog</name>
    <message>
        <source>Canned cycle</source>
        <translation>Cykl stały</translation>
    </message>
    <message>
        <source>* required</source>
        <translation>* wymagane</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FagorTableModel</name>
    <message>
        <source>Key</source>
        <translation>Klucz</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FileManager</name>
    <message>
        <source>All files</source>
        <translation>Wszystkie pliki</translation>
    </message>
    <message>
        <source>Programs (.H .I .PIT)</source>
        <translation>Programy (.H .I .PIT)</translation>
    </message>
    <message>
        <source>NC root: %1</source>
        <translation>Katalog NC: %1</translation>
    </message>
    <message>
        <source>Recent files</source>
        <translation>Ostatnie pliki</translation>
    </message>
    <message>
        <source>File manager</source>
        <translation>Zarządzanie plikami</translation>
    </message>
    <message>
        <source>Copy %1 to:</source>
        <translation>Kopiuj %1 do:</translation>
    </message>
    <message>
        <source>Copied to %1</source>
        <translation>Skopiowano do %1</translation>
    </message>
    <message>
        <source>Move %1 to folder:</source>
        <translation>Przenieś %1 do katalogu:</translation>
    </message>
    <message>
        <source>New name for %1:</source>
        <translation>Nowa nazwa dla %1:</translation>
    </message>
    <message>
        <source>Delete %1?</source>
        <translation>Usunąć %1?</translation>
    </message>
    <message>
        <source>Name of the new folder:</source>
        <translation>Nazwa nowego katalogu:</translation>
    </message>
    <message>
        <source>Tables (.T .TCH .PR .D .PNT .TP .TAB)</source>
        <translation>Tabele (.T .TCH .PR .D .PNT .TP .TAB)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FindBar</name>
    <message>
        <source>Find</source>
        <translation>Szukaj</translation>
    </message>
    <message>
        <source>Replace with</source>
        <translation>Zamień na</translation>
    </message>
    <message>
        <source>Match case</source>
        <translation>Uwzględnij wielkość liter</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>Poprzedni</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Następny</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Zamień</translation>
    </message>
    <message>
        <source>Replace all</source>
        <translation>Zamień wszystko</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zamknij</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Nie znaleziono</translation>
    </message>
    <message numerus="yes">
        <source>%n replaced</source>
        <translation>
            <numerusform>Zamieniono %n</numerusform>
            <numerusform>Zamieniono %n</numerusform>
            <numerusform>Zamieniono %n</numerusform>
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
        <translation>Element FK określony</translation>
    </message>
    <message>
        <source>FK element not determined</source>
        <translation>Element FK nieokreślony</translation>
    </message>
    <message>
        <source>Solution %1 of %2</source>
        <translation>Rozwiązanie %1 z %2</translation>
    </message>
    <message>
        <source>Other solutions</source>
        <translation>Inne rozwiązania</translation>
    </message>
    <message>
        <source>FK element with solution 1 assumed (no FSELECT)</source>
        <translation>Element FK z przyjętym rozwiązaniem 1 (brak FSELECT)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::GraphicsPanel</name>
    <message>
        <source>The 3D graphics need a display</source>
        <translation>Grafika 3D wymaga wyświetlacza</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Prędkość</translation>
    </message>
    <message>
        <source>Machining time %1</source>
        <translation>Czas obróbki %1</translation>
    </message>
    <message>
        <source>%1   %2 % done   %3 remaining</source>
        <translation>%1   %2 % wykonano   pozostało %3</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineKeys</name>
    <message>
        <source>Machine on</source>
        <translation>Maszyna wł.</translation>
    </message>
    <message>
        <source>EMERGENCY STOP</source>
        <translation>STOP AWARYJNY</translation>
    </message>
    <message>
        <source>Release EMERGENCY STOP</source>
        <translation>Odblokuj STOP AWARYJNY</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineSession</name>
    <message>
        <source>The machine is busy: stop the program or wait until the axes stand still</source>
        <translation>Maszyna jest zajęta: zatrzymaj program lub poczekaj, aż osie staną</translation>
    </message>
    <message>
        <source>The program has errors and cannot be started</source>
        <translation>Program zawiera błędy i nie może zostać uruchomiony</translation>
    </message>
    <message>
        <source>Program finished</source>
        <translation>Program zakończony</translation>
    </message>
    <message>
        <source>Program stopped</source>
        <translation>Program zatrzymany</translation>
    </message>
    <message>
        <source>The preset could not be saved in PRESET.PR, so the next program uses the table&apos;s preset again: %1</source>
        <translation>Nie można zapisać punktu odniesienia w PRESET.PR, więc następny program użyje ponownie punktu odniesienia z tabeli: %1</translation>
    </message>
    <message>
        <source>The machine is off (emergency stop or drive fault): switch it on with Machine on</source>
        <translation>Maszyna jest wyłączona (stop awaryjny lub błąd napędu): włącz ją przyciskiem Maszyna wł.</translation>
    </message>
    <message>
        <source>The machine is on already</source>
        <translation>Maszyna jest już włączona</translation>
    </message>
    <message>
        <source>The axes are not referenced: run Home all in Manual operation first</source>
        <translation>Osie nie są zbazowane: najpierw wykonaj Bazuj wszystkie w Obsłudze ręcznej</translation>
    </message>
    <message>
        <source>The emergency stop button is pressed: release it, then Machine on</source>
        <translation>Wyłącznik awaryjny jest wciśnięty: odblokuj go, potem Maszyna wł.</translation>
    </message>
    <message>
        <source>Release the emergency stop button first</source>
        <translation>Najpierw odblokuj wyłącznik awaryjny</translation>
    </message>
    <message>
        <source>The emergency stop chain is still open</source>
        <translation>Obwód wyłącznika awaryjnego jest nadal otwarty</translation>
    </message>
    <message>
        <source>Probing: the stylus is deflected already</source>
        <translation>Pomiar: trzpień jest już wychylony</translation>
    </message>
    <message>
        <source>Probing: no touch within %1 mm</source>
        <translation>Pomiar: brak styku w zakresie %1 mm</translation>
    </message>
    <message>
        <source>The basic rotation could not be saved in PRESET.PR: %1</source>
        <translation>Nie można zapisać obrotu podstawowego w PRESET.PR: %1</translation>
    </message>
    <message>
        <source>The tool offset must be D1 to D255</source>
        <translation>Korekcja narzędzia musi być od D1 do D255</translation>
    </message>
    <message>
        <source>Tool calibration: %1</source>
        <translation>Kalibracja narzędzia: %1</translation>
    </message>
    <message>
        <source>Tool calibration works on X and Z only</source>
        <translation>Kalibracja narzędzia działa tylko dla X i Z</translation>
    </message>
    <message>
        <source>Tool %1: L = %2 mm</source>
        <translation>Narzędzie %1: L = %2 mm</translation>
    </message>
    <message>
        <source>The probing log TCHPRMAN.html could not be written: %1</source>
        <translation>Nie można zapisać protokołu pomiaru TCHPRMAN.html: %1</translation>
    </message>
    <message>
        <source>Tool offset D%1: X = %2 mm (radius)</source>
        <translation>Korekcja narzędzia D%1: X = %2 mm (promień)</translation>
    </message>
    <message>
        <source>Tool offset D%1: Z = %2 mm</source>
        <translation>Korekcja narzędzia D%1: Z = %2 mm</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MainWindow</name>
    <message>
        <source>Programming station</source>
        <translation>Stanowisko programowania</translation>
    </message>
    <message>
        <source>%1 has unsaved changes from an earlier session: press &quot;Restore autosave&quot; to get them back</source>
        <translation>%1 ma niezapisane zmiany z poprzedniej sesji: naciśnij &quot;Przywróć autozapis&quot;, aby je odzyskać</translation>
    </message>
    <message>
        <source>Kerf - %1</source>
        <translation>Kerf - %1</translation>
    </message>
    <message>
        <source>Screen
layout</source>
        <translation>Podział
ekranu</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Pliki</translation>
    </message>
    <message>
        <source>Tool
table</source>
        <translation>Tabela
narzędzi</translation>
    </message>
    <message>
        <source>Message
list</source>
        <translation>Lista
komunikatów</translation>
    </message>
    <message>
        <source>Clear
messages</source>
        <translation>Usuń
komunikaty</translation>
    </message>
    <message>
        <source>Language
%1</source>
        <translation>Język
%1</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Otwórz</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopiuj</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Przenieś</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Zmień
nazwę</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Usuń</translation>
    </message>
    <message>
        <source>Protect /
unprotect</source>
        <translation>Chroń /
odblokuj</translation>
    </message>
    <message>
        <source>New
folder</source>
        <translation>Nowy
katalog</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Powrót</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Zapisz</translation>
    </message>
    <message>
        <source>Insert
row</source>
        <translation>Wstaw
wiersz</translation>
    </message>
    <message>
        <source>Delete
row</source>
        <translation>Usuń
wiersz</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Cofnij</translation>
    </message>
    <message>
        <source>Find /
replace</source>
        <translation>Szukaj /
zamień</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Ponów</translation>
    </message>
    <message>
        <source>Renumber
blocks</source>
        <translation>Numeruj
bloki</translation>
    </message>
    <message>
        <source>Check
program</source>
        <translation>Sprawdź
program</translation>
    </message>
    <message>
        <source>Restore
autosave</source>
        <translation>Przywróć
autozapis</translation>
    </message>
    <message>
        <source>Tables</source>
        <translation>Tabele</translation>
    </message>
    <message>
        <source>MOD</source>
        <translation>MOD</translation>
    </message>
    <message>
        <source>No program is open: open one in Files</source>
        <translation>Żaden program nie jest otwarty: otwórz program w Plikach</translation>
    </message>
    <message>
        <source>Machine
parameters</source>
        <translation>Parametry
maszynowe</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <source>Speed
%1</source>
        <translation>Prędkość
%1</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Widok</translation>
    </message>
    <message>
        <source>Zoom
+</source>
        <translation>Powiększ
+</translation>
    </message>
    <message>
        <source>Zoom
-</source>
        <translation>Pomniejsz
-</translation>
    </message>
    <message>
        <source>New
program</source>
        <translation>Nowy
program</translation>
    </message>
    <message>
        <source>Go to
block</source>
        <translation>Idź do
bloku</translation>
    </message>
    <message>
        <source>Go to block</source>
        <translation>Idź do bloku</translation>
    </message>
    <message>
        <source>The program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Niezapisane zmiany</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 ma niezapisane zmiany. Zapisać je?</translation>
    </message>
    <message>
        <source>A program is running. Stop it and quit?</source>
        <translation>Program jest wykonywany. Zatrzymać go i zakończyć?</translation>
    </message>
    <message>
        <source>The spindle turns. Stop it and quit?</source>
        <translation>Wrzeciono się obraca. Zatrzymać je i zakończyć?</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Zakończ</translation>
    </message>
    <message>
        <source>Start at block</source>
        <translation>Start od bloku</translation>
    </message>
    <message>
        <source>No user customisation program: %1 is not in the NC root</source>
        <translation>Brak programu personalizacji użytkownika: %1 nie ma w katalogu NC</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Użytkownik</translation>
    </message>
    <message>
        <source>Leave
user screen</source>
        <translation>Opuść ekran
użytkownika</translation>
    </message>
    <message>
        <source>The program in the editor is protected: the block %1 of the user screen was not inserted</source>
        <translation>Program w edytorze jest chroniony: blok %1 ekranu użytkownika nie został wstawiony</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MdiDialog</name>
    <message>
        <source>Positioning with MDI</source>
        <translation>Pozycjonowanie z MDI</translation>
    </message>
    <message>
        <source>Block (arrow keys: the blocks run before)</source>
        <translation>Blok (klawisze strzałek: bloki wykonane wcześniej)</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MessagePanel</name>
    <message>
        <source>Severity</source>
        <translation>Waga</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Komunikat</translation>
    </message>
    <message>
        <source>No messages</source>
        <translation>Brak komunikatów</translation>
    </message>
    <message>
        <source>%1 - %2%3</source>
        <translation>%1 - %2%3</translation>
    </message>
    <message numerus="yes">
        <source> (%n more)</source>
        <translation>
            <numerusform> (jeszcze %n)</numerusform>
            <numerusform> (jeszcze %n)</numerusform>
            <numerusform> (jeszcze %n)</numerusform>
        </translation>
    </message>
    <message>
        <source>Block</source>
        <translation>Blok</translation>
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
        <translation>Funkcje MOD</translation>
    </message>
    <message>
        <source>Position display</source>
        <translation>Wyświetlanie położenia</translation>
    </message>
    <message>
        <source>Unit of the position display</source>
        <translation>Jednostka wyświetlania położenia</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Język</translation>
    </message>
    <message>
        <source>Software: Kerf %1 (Qt %2)
Machine: %3</source>
        <translation>Oprogramowanie: Kerf %1 (Qt %2)
Maszyna: %3</translation>
    </message>
    <message>
        <source>Kerf is free software: you may share and change it under the GNU General Public License, version 3 or later. It comes with no warranty.</source>
        <translation>Kerf jest wolnym oprogramowaniem: można je rozpowszechniać i zmieniać na warunkach Powszechnej Licencji Publicznej GNU w wersji 3 lub późniejszej. Nie jest objęte żadną gwarancją.</translation>
    </message>
</context>
<context>
    <name>kerf::ui::NewProgramDialog</name>
    <message>
        <source>New program</source>
        <translation>Nowy program</translation>
    </message>
    <message>
        <source>Program name</source>
        <translation>Nazwa programu</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Jednostka</translation>
    </message>
    <message>
        <source>Blank MIN %1</source>
        <translation>Półfabrykat MIN %1</translation>
    </message>
    <message>
        <source>Blank MAX %1</source>
        <translation>Półfabrykat MAX %1</translation>
    </message>
    <message>
        <source>Give the program a name without spaces or folders</source>
        <translation>Nadaj programowi nazwę bez spacji i folderów</translation>
    </message>
    <message>
        <source>The blank&apos;s MIN point must lie below its MAX point on every axis</source>
        <translation>Punkt MIN półfabrykatu musi leżeć poniżej punktu MAX na każdej osi</translation>
    </message>
</context>
<context>
    <name>kerf::ui::OperatorInputDialog</name>
    <message>
        <source>Operator inputs</source>
        <translation>Dane operatora</translation>
    </message>
    <message>
        <source>The program reads these inputs: enter their values</source>
        <translation>Program odczytuje te dane: wpisz ich wartości</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
</context>
<context>
    <name>kerf::ui::OverrideControls</name>
    <message>
        <source>Feed</source>
        <translation>Posuw</translation>
    </message>
    <message>
        <source>Rapid</source>
        <translation>Bieg szybki</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Wrzeciono</translation>
    </message>
</context>
<context>
    <name>kerf::ui::PathFunctionDialog</name>
    <message>
        <source>Path function</source>
        <translation>Funkcja toru</translation>
    </message>
</context>
<context>
    <name>kerf::ui::PositionDisplay</name>
    <message>
        <source>ACTL.</source>
        <translation>RZECZ.</translation>
    </message>
    <message>
        <source>NOML.</source>
        <translation>ZAD.</translation>
    </message>
    <message>
        <source>REF ACTL.</source>
        <translation>REF RZECZ.</translation>
    </message>
    <message>
        <source>REF NOML.</source>
        <translation>REF ZAD.</translation>
    </message>
    <message>
        <source>LAG</source>
        <translation>UCHYB</translation>
    </message>
    <message>
        <source>DIST.</source>
        <translation>ODL.</translation>
    </message>
    <message>
        <source>Program: %1   Machine: %2</source>
        <translation>Program: %1   Maszyna: %2</translation>
    </message>
    <message>
        <source>T %1</source>
        <translation>T %1</translation>
    </message>
    <message>
        <source>F %1 (actual %2) %3</source>
        <translation>F %1 (rzeczywisty %2) %3</translation>
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
        <translation>S %1 (rzeczywista %2) obr/min</translation>
    </message>
    <message>
        <source>Not referenced: Home all in Manual operation</source>
        <translation>Niezbazowana: Bazuj wszystkie w Obsłudze ręcznej</translation>
    </message>
    <message>
        <source>Coolant on</source>
        <translation>Chłodziwo wł.</translation>
    </message>
    <message>
        <source>Coolant off</source>
        <translation>Chłodziwo wył.</translation>
    </message>
    <message>
        <source>inch/rev</source>
        <translation>inch/obr</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/obr</translation>
    </message>
    <message>
        <source>S %1 ft/min (actual %2 rpm)</source>
        <translation>S %1 ft/min (rzeczywista %2 obr/min)</translation>
    </message>
    <message>
        <source>S %1 m/min (actual %2 rpm)</source>
        <translation>S %1 m/min (rzeczywista %2 obr/min)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::ProgramFileDialog</name>
    <message>
        <source>Select file</source>
        <translation>Wybierz plik</translation>
    </message>
    <message>
        <source>NC root: %1</source>
        <translation>Katalog NC: %1</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
    <message>
        <source>Choose a program (.H or .I)</source>
        <translation>Wybierz program (.H lub .I)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::ProgramPanel</name>
    <message>
        <source>Saved %1</source>
        <translation>Zapisano %1</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Autozapis nie powiódł się: %1</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>Brak programu</translation>
    </message>
    <message>
        <source>Loading %1 ...</source>
        <translation>Wczytywanie %1 ...</translation>
    </message>
    <message>
        <source>Checking the program: it runs without moving the machine</source>
        <translation>Sprawdzanie programu: program jest wykonywany bez ruchu maszyny</translation>
    </message>
    <message>
        <source>Program check: no errors, the program runs to its end</source>
        <translation>Sprawdzenie programu: brak błędów, program wykonuje się do końca</translation>
    </message>
    <message>
        <source>Program check: the program cannot run (errors: %1)</source>
        <translation>Sprawdzenie programu: programu nie można wykonać (błędy: %1)</translation>
    </message>
    <message>
        <source>%1 was not opened: %2 could not be saved</source>
        <translation>%1 nie został otwarty: nie można zapisać %2</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SettingsModel</name>
    <message>
        <source>Machine</source>
        <translation>Maszyna</translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation>Oś %1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parametr</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wartość</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Jednostka</translation>
    </message>
    <message>
        <source>Allowed</source>
        <translation>Dozwolone</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Domyślnie</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Opis</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SettingsPage</name>
    <message>
        <source>Not saved: correct the parameters first</source>
        <translation>Nie zapisano: najpierw popraw parametry</translation>
    </message>
    <message>
        <source>Saved %1: the changes apply when Kerf is restarted</source>
        <translation>Zapisano %1: zmiany obowiązują po ponownym uruchomieniu Kerf</translation>
    </message>
    <message>
        <source>Machine parameters</source>
        <translation>Parametry maszynowe</translation>
    </message>
    <message>
        <source>Kerf reads the machine parameters when it starts: saved changes apply after a restart. This is a built-in machine: the parameters are saved to %1; start Kerf with --machine %1 to use them.</source>
        <translation>Kerf wczytuje parametry maszynowe przy starcie: zapisane zmiany obowiązują po ponownym uruchomieniu. To jest maszyna wbudowana: parametry zostaną zapisane w %1; uruchom Kerf z --machine %1, aby ich użyć.</translation>
    </message>
    <message>
        <source>Kerf reads the machine parameters when it starts: saved changes to %1 apply after a restart.</source>
        <translation>Kerf wczytuje parametry maszynowe przy starcie: zmiany zapisane w %1 obowiązują po ponownym uruchomieniu.</translation>
    </message>
    <message>
        <source>Wrong code number: the machine parameters stay locked</source>
        <translation>Błędny kod liczbowy: parametry maszyny pozostają zablokowane</translation>
    </message>
    <message>
        <source>Machine parameters unlocked for editing</source>
        <translation>Parametry maszyny odblokowane do edycji</translation>
    </message>
    <message>
        <source>Code number for editing</source>
        <translation>Kod liczbowy do edycji</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Odblokuj</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SpecialFunctionDialog</name>
    <message>
        <source>Special function</source>
        <translation>Funkcja specjalna</translation>
    </message>
    <message>
        <source>Select file</source>
        <translation>Wybierz plik</translation>
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
        <translation>Filtr, np. %1</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Called program</source>
        <translation>Wywołany program</translation>
    </message>
    <message>
        <source>Label</source>
        <translation>Etykieta</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>Cykl</translation>
    </message>
    <message>
        <source>M functions</source>
        <translation>Funkcje M</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Jednostka</translation>
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
        <translation>Narzędzie</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nazwa</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Korekcja</translation>
    </message>
    <message>
        <source>X (radius)</source>
        <translation>X (promień)</translation>
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
        <translation>Zużycie X (I)</translation>
    </message>
    <message>
        <source>Wear Z (K)</source>
        <translation>Zużycie Z (K)</translation>
    </message>
    <message>
        <source>Location code (F)</source>
        <translation>Kod położenia (F)</translation>
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
        <translation>Oś narzędzia</translation>
    </message>
    <message>
        <source>Zero offset</source>
        <translation>Przesunięcie punktu zerowego</translation>
    </message>
    <message>
        <source>Datum shift %1</source>
        <translation>Przesunięcie punktu zerowego %1</translation>
    </message>
    <message>
        <source>Mirrored axes</source>
        <translation>Odbite osie</translation>
    </message>
    <message>
        <source>Rotation</source>
        <translation>Obrót</translation>
    </message>
    <message>
        <source>Scaling</source>
        <translation>Skalowanie</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wartość</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Rodzaj</translation>
    </message>
    <message>
        <source>global</source>
        <translation>globalny</translation>
    </message>
    <message>
        <source>local, level %1</source>
        <translation>lokalny, poziom %1</translation>
    </message>
    <message>
        <source>local</source>
        <translation>lokalny</translation>
    </message>
    <message>
        <source>remanent</source>
        <translation>remanentny</translation>
    </message>
    <message>
        <source>text</source>
        <translation>tekst</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Sonda</translation>
    </message>
    <message>
        <source>no result</source>
        <translation>brak wyniku</translation>
    </message>
    <message>
        <source>touched</source>
        <translation>zetknięcie</translation>
    </message>
    <message>
        <source>not touched</source>
        <translation>brak zetknięcia</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Wrzeciono</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Posuw</translation>
    </message>
    <message>
        <source>S %1 %2 (constant surface speed)</source>
        <translation>S %1 %2 (stała prędkość skrawania)</translation>
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
        <translation>S %1 obr/min</translation>
    </message>
    <message>
        <source>limit %1 rpm</source>
        <translation>ograniczenie %1 obr/min</translation>
    </message>
    <message>
        <source>in/rev</source>
        <translation>in/obr</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/obr</translation>
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
        <translation>Blok</translation>
    </message>
    <message>
        <source>Working plane</source>
        <translation>Płaszczyzna obróbki</translation>
    </message>
    <message>
        <source>Working plane %1</source>
        <translation>Płaszczyzna obróbki %1</translation>
    </message>
    <message>
        <source>Rotary axes</source>
        <translation>Osie obrotowe</translation>
    </message>
    <message>
        <source>Manual probing</source>
        <translation>Pomiar ręczny sondą</translation>
    </message>
    <message>
        <source>Basic rotation</source>
        <translation>Obrót podstawowy</translation>
    </message>
    <message>
        <source>Probed %1</source>
        <translation>Zmierzono %1</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>Średnica</translation>
    </message>
    <message>
        <source>Plane A</source>
        <translation>Płaszczyzna A</translation>
    </message>
    <message>
        <source>Plane B</source>
        <translation>Płaszczyzna B</translation>
    </message>
    <message>
        <source>Tool length T%1</source>
        <translation>Długość narzędzia T%1</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Stan</translation>
    </message>
    <message>
        <source>follows when the program is prepared</source>
        <translation>pojawi się po przygotowaniu programu</translation>
    </message>
    <message>
        <source>none</source>
        <comment>cycle</comment>
        <translation>brak</translation>
    </message>
    <message>
        <source>none</source>
        <comment>program</comment>
        <translation>brak</translation>
    </message>
    <message>
        <source>none</source>
        <comment>called program</comment>
        <translation>brak</translation>
    </message>
    <message>
        <source>none</source>
        <comment>label</comment>
        <translation>brak</translation>
    </message>
    <message>
        <source>none</source>
        <comment>M functions</comment>
        <translation>brak</translation>
    </message>
    <message>
        <source>none</source>
        <comment>tool</comment>
        <translation>brak</translation>
    </message>
    <message>
        <source>none</source>
        <comment>mirrored axes</comment>
        <translation>brak</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TableChooser</name>
    <message>
        <source>Tool
table</source>
        <translation>Tabela
narzędzi</translation>
    </message>
    <message>
        <source>Preset
table</source>
        <translation>Tabela punktów
odniesienia</translation>
    </message>
    <message>
        <source>Datum
table</source>
        <translation>Tabela punktów
zerowych</translation>
    </message>
    <message>
        <source>Point
table</source>
        <translation>Tabela
punktów</translation>
    </message>
    <message>
        <source>Touch probe
table</source>
        <translation>Tabela
sond</translation>
    </message>
    <message>
        <source>Tool
offsets</source>
        <translation>Korekcje
narzędzi</translation>
    </message>
    <message>
        <source>Zero
offsets</source>
        <translation>Przesunięcia
punktu zerowego</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabela</translation>
    </message>
    <message>
        <source>Lengths, radii, wear and life of the tools</source>
        <translation>Długości, promienie, zużycie i okres trwałości narzędzi</translation>
    </message>
    <message>
        <source>Reference points of the workpieces, in machine coordinates</source>
        <translation>Punkty odniesienia obrabianych przedmiotów we współrzędnych maszyny</translation>
    </message>
    <message>
        <source>Zero offsets relative to the active preset (CYCL DEF 7)</source>
        <translation>Punkty zerowe względem aktywnego punktu odniesienia (CYCL DEF 7)</translation>
    </message>
    <message>
        <source>Machining positions for patterns (SEL PATTERN)</source>
        <translation>Pozycje obróbki dla wzorów (SEL PATTERN)</translation>
    </message>
    <message>
        <source>Workpiece touch probes: centre offset, feeds, probing path</source>
        <translation>Sondy przedmiotowe: przesunięcie środka, posuwy, droga próbkowania</translation>
    </message>
    <message>
        <source>Tool offsets D: X, Z, nose radius R, location code F, wear I, K</source>
        <translation>Korekcje narzędzi D: X, Z, promień ostrza R, kod położenia F, zużycie I, K</translation>
    </message>
    <message>
        <source>Zero offsets G54-G59, G159 N7-N20 and the PLC offset, from machine zero</source>
        <translation>Przesunięcia punktu zerowego G54-G59, G159 N7-N20 i przesunięcie PLC, od zera maszyny</translation>
    </message>
    <message>
        <source>Tools T: offset D, family, tool life, nose angle and width</source>
        <translation>Narzędzia T: korekcja D, rodzina, okres trwałości, kąt i szerokość ostrza</translation>
    </message>
    <message>
        <source>Tables</source>
        <translation>Tabele</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TableEditor</name>
    <message>
        <source>No table</source>
        <translation>Brak tabeli</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Szukaj</translation>
    </message>
    <message>
        <source>Not saved: correct the table first</source>
        <translation>Nie zapisano: najpierw popraw tabelę</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Zapisano %1</translation>
    </message>
    <message>
        <source>Delete row %1 (%2)?</source>
        <translation>Usunąć wiersz %1 (%2)?</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabela</translation>
    </message>
    <message>
        <source>%1 was changed on disk (e.g. by a tool measurement): reloaded</source>
        <translation>%1 zmieniono na dysku (np. przez pomiar narzędzia): wczytano ponownie</translation>
    </message>
    <message>
        <source>%1 was changed on disk while you edit it: saving would overwrite those changes</source>
        <translation>%1 zmieniono na dysku podczas edycji: zapis nadpisałby te zmiany</translation>
    </message>
    <message>
        <source>%1 was changed on disk since it was opened here (e.g. by a tool measurement). Overwrite it with the table shown?</source>
        <translation>%1 zmieniono na dysku od otwarcia tutaj (np. przez pomiar narzędzia). Nadpisać ją wyświetlaną tabelą?</translation>
    </message>
    <message>
        <source>Not saved: the file on disk is kept</source>
        <translation>Nie zapisano: plik na dysku pozostaje</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TestRunController</name>
    <message>
        <source>max</source>
        <translation>maks.</translation>
    </message>
    <message>
        <source>Test run: %1</source>
        <translation>Test programu: %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::UserScreenView</name>
    <message>
        <source>User screen</source>
        <translation>Ekran użytkownika</translation>
    </message>
    <message>
        <source>User screen - page %1</source>
        <translation>Ekran użytkownika - strona %1</translation>
    </message>
    <message>
        <source>Enter IB%1 (format %2%3.%4) and press Enter</source>
        <translation>Wprowadź IB%1 (format %2%3.%4) i naciśnij Enter</translation>
    </message>
    <message>
        <source>Waiting for a key: press a softkey</source>
        <translation>Oczekiwanie na klawisz: naciśnij softkey</translation>
    </message>
    <message>
        <source>The customisation program has ended</source>
        <translation>Program personalizacji zakończył się</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Działa</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Zatrzymany</translation>
    </message>
    <message>
        <source>Block being edited: %1</source>
        <translation>Edytowany blok: %1</translation>
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
        <translation>Z góry</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Z przodu</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Z boku</translation>
    </message>
    <message>
        <source>Section</source>
        <translation>Przekrój</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Dopasuj</translation>
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
        <translation>Anuluj</translation>
    </message>
</context>
<context>
    <name>kerf::ui::Workspace</name>
    <message>
        <source>Program</source>
        <translation>Program</translation>
    </message>
    <message>
        <source>Program +
graphics</source>
        <translation>Program +
grafika</translation>
    </message>
    <message>
        <source>Program +
status</source>
        <translation>Program +
status</translation>
    </message>
    <message>
        <source>Positions +
status</source>
        <translation>Pozycje +
status</translation>
    </message>
</context>
<context>
    <name>kerf</name>
    <message>
        <source>programming station: no machine is connected, only Programming and Test run are available</source>
        <translation>stanowisko programowania: brak podłączonej maszyny, dostępne są tylko Programowanie i Test programu</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Uwaga</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Ostrzeżenie</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Błąd</translation>
    </message>
    <message>
        <source>Manual operation</source>
        <translation>Obsługa ręczna</translation>
    </message>
    <message>
        <source>Electronic handwheel</source>
        <translation>Elektroniczne kółko ręczne</translation>
    </message>
    <message>
        <source>Positioning with manual data input</source>
        <translation>Pozycjonowanie z ręcznym wprowadzeniem danych</translation>
    </message>
    <message>
        <source>Program run, single block</source>
        <translation>Przebieg programu, pojedynczy blok</translation>
    </message>
    <message>
        <source>Program run, full sequence</source>
        <translation>Przebieg programu, sekwencja bloków</translation>
    </message>
    <message>
        <source>Programming</source>
        <translation>Programowanie</translation>
    </message>
    <message>
        <source>Test run</source>
        <translation>Test programu</translation>
    </message>
    <message>
        <source>stop the program before changing the operating mode</source>
        <translation>zatrzymaj program przed zmianą trybu pracy</translation>
    </message>
    <message>
        <source>cannot {1}: {2}</source>
        <translation>nie można {1}: {2}</translation>
    </message>
    <message>
        <source>Set-up clearance: tool tip to workpiece surface</source>
        <translation>Odstęp bezpieczeństwa: wierzchołek narzędzia do powierzchni obrabianego przedmiotu</translation>
    </message>
    <message>
        <source>Depth: workpiece surface to bottom (sign = direction)</source>
        <translation>Głębokość: powierzchnia obrabianego przedmiotu do dna (znak = kierunek)</translation>
    </message>
    <message>
        <source>Thread depth: workpiece surface to thread end</source>
        <translation>Głębokość gwintu: powierzchnia obrabianego przedmiotu do końca gwintu</translation>
    </message>
    <message>
        <source>Plunging depth per infeed</source>
        <translation>Głębokość dosuwu na jedno wcięcie</translation>
    </message>
    <message>
        <source>Workpiece surface coordinate</source>
        <translation>Współrzędne powierzchni obrabianego przedmiotu</translation>
    </message>
    <message>
        <source>2nd set-up clearance: no collision above this height</source>
        <translation>2. odstęp bezpieczeństwa: brak kolizji powyżej tej wysokości</translation>
    </message>
    <message>
        <source>Minimum plunging depth when decreasing</source>
        <translation>Minimalna głębokość dosuwu przy zmniejszaniu</translation>
    </message>
    <message>
        <source>Feed rate for plunging</source>
        <translation>Posuw wcięcia w materiał</translation>
    </message>
    <message>
        <source>Feed rate for milling</source>
        <translation>Posuw frezowania</translation>
    </message>
    <message>
        <source>Retraction feed rate (0: plunging feed)</source>
        <translation>Posuw powrotu (0: posuw wcięcia)</translation>
    </message>
    <message>
        <source>Dwell time at the top</source>
        <translation>Czas przerwy u góry</translation>
    </message>
    <message>
        <source>Dwell time at depth</source>
        <translation>Czas przerwy na dole</translation>
    </message>
    <message>
        <source>Decrement of the plunging depth after each infeed</source>
        <translation>Zmniejszenie głębokości dosuwu po każdym wcięciu</translation>
    </message>
    <message>
        <source>Feed rate for pre-positioning</source>
        <translation>Posuw pozycjonowania wstępnego</translation>
    </message>
    <message>
        <source>Feed rate for countersinking</source>
        <translation>Posuw pogłębiania</translation>
    </message>
    <message>
        <source>Retraction distance for chip breaking</source>
        <translation>Odcinek powrotu przy łamaniu wióra</translation>
    </message>
    <message>
        <source>Depth for chip breaking (0: none)</source>
        <translation>Głębokość łamania wióra (0: brak)</translation>
    </message>
    <message>
        <source>Upper advanced stop distance</source>
        <translation>Górny odstęp wyprzedzenia</translation>
    </message>
    <message>
        <source>Angle for spindle orientation</source>
        <translation>Kąt orientacji wrzeciona</translation>
    </message>
    <message>
        <source>Disengaging direction (0 none, 1 -main, 2 -secondary, 3 +main, 4 +secondary axis)</source>
        <translation>Kierunek odsunięcia (0 brak, 1 -oś główna, 2 -oś pomocnicza, 3 +oś główna, 4 +oś pomocnicza)</translation>
    </message>
    <message>
        <source>Nominal diameter</source>
        <translation>Średnica nominalna</translation>
    </message>
    <message>
        <source>Thread pitch (+ right-hand, - left-hand)</source>
        <translation>Skok gwintu (+ prawy, - lewy)</translation>
    </message>
    <message>
        <source>Climb (+1) or up-cut (-1) milling with M3</source>
        <translation>Frezowanie współbieżne (+1) lub przeciwbieżne (-1) z M3</translation>
    </message>
    <message>
        <source>Threads per step (0 one 360° helix, 1 continuous)</source>
        <translation>Liczba zwojów na krok (0 jedna linia śrubowa 360°, 1 ciągle)</translation>
    </message>
    <message>
        <source>Countersinking depth: surface to tool tip</source>
        <translation>Głębokość pogłębienia: powierzchnia do wierzchołka narzędzia</translation>
    </message>
    <message>
        <source>Total hole depth</source>
        <translation>Całkowita głębokość otworu</translation>
    </message>
    <message>
        <source>Clearance to side: tool edge to hole wall</source>
        <translation>Odstęp z boku: krawędź narzędzia do ścianki otworu</translation>
    </message>
    <message>
        <source>Depth at front: surface to tool tip</source>
        <translation>Głębokość czołowo: powierzchnia do wierzchołka narzędzia</translation>
    </message>
    <message>
        <source>Countersinking offset at front (tool centre)</source>
        <translation>Przesunięcie pogłębienia czołowo (środek narzędzia)</translation>
    </message>
    <message>
        <source>Feed rate for approaching (0: milling feed)</source>
        <translation>Posuw najazdu (0: posuw frezowania)</translation>
    </message>
    <message>
        <source>Deepened starting point below the surface</source>
        <translation>Pogłębiony punkt startu poniżej powierzchni</translation>
    </message>
    <message>
        <source>Depth reference (0 tool tip, 1 cylindrical part)</source>
        <translation>Odniesienie głębokości (0 wierzchołek narzędzia, 1 część cylindryczna)</translation>
    </message>
    <message>
        <source>cycle {1}: {2} ({3}) = {4} must be a whole number from {5} to {6}</source>
        <translation>cykl {1}: {2} ({3}) = {4} musi być liczbą całkowitą od {5} do {6}</translation>
    </message>
    <message>
        <source>cycle {1}: {2} ({3}) = {4} is outside {5} to {6}</source>
        <translation>cykl {1}: {2} ({3}) = {4} leży poza zakresem {5} do {6}</translation>
    </message>
    <message>
        <source>DRILLING</source>
        <translation>WIERCENIE</translation>
    </message>
    <message>
        <source>REAMING</source>
        <translation>ROZWIERCANIE DOKŁADNE OTWORU</translation>
    </message>
    <message>
        <source>BORING</source>
        <translation>WYTACZANIE</translation>
    </message>
    <message>
        <source>Number of chip breaks before retracting</source>
        <translation>Liczba łamań wióra przed wycofaniem</translation>
    </message>
    <message>
        <source>UNIVERSAL DRILLING</source>
        <translation>WIERCENIE UNIWERSALNE</translation>
    </message>
    <message>
        <source>Depth of counterbore from the underside (+ upwards)</source>
        <translation>Głębokość pogłębienia od dolnej strony (+ w górę)</translation>
    </message>
    <message>
        <source>Material thickness</source>
        <translation>Grubość materiału</translation>
    </message>
    <message>
        <source>Off-centre distance of the boring bar</source>
        <translation>Wymiar mimośrodu wytaczadła</translation>
    </message>
    <message>
        <source>Tool edge height above the underside of the bar</source>
        <translation>Wysokość ostrza narzędzia nad dolną krawędzią wytaczadła</translation>
    </message>
    <message>
        <source>Feed rate for counterboring</source>
        <translation>Posuw pogłębiania</translation>
    </message>
    <message>
        <source>Dwell time at the counterbore floor</source>
        <translation>Czas przerwy na dnie pogłębienia</translation>
    </message>
    <message>
        <source>Disengaging direction (1 -main, 2 -secondary, 3 +main, 4 +secondary axis)</source>
        <translation>Kierunek odsunięcia (1 -oś główna, 2 -oś pomocnicza, 3 +oś główna, 4 +oś pomocnicza)</translation>
    </message>
    <message>
        <source>BACK BORING</source>
        <translation>POGŁĘBIANIE WSTECZNE</translation>
    </message>
    <message>
        <source>Lower advanced stop distance</source>
        <translation>Dolny odstęp wyprzedzenia</translation>
    </message>
    <message>
        <source>cycle {1}: the starting point Q379 lies at or below the depth</source>
        <translation>cykl {1}: punkt startu Q379 leży na głębokości lub poniżej niej</translation>
    </message>
    <message>
        <source>UNIVERSAL PECKING</source>
        <translation>WIERCENIE GŁĘBOKIE UNIWERSALNE</translation>
    </message>
    <message>
        <source>Feed rate for helical drilling</source>
        <translation>Posuw wiercenia po linii śrubowej</translation>
    </message>
    <message>
        <source>Infeed per helix revolution</source>
        <translation>Dosuw na jeden obrót linii śrubowej</translation>
    </message>
    <message>
        <source>Roughing (pre-drilled) diameter</source>
        <translation>Średnica wstępnie obrobiona (nawiercona)</translation>
    </message>
    <message>
        <source>cycle {1}: the nominal diameter {2} is smaller than the tool diameter {3}</source>
        <translation>cykl {1}: średnica nominalna {2} jest mniejsza od średnicy narzędzia {3}</translation>
    </message>
    <message>
        <source>cycle {1}: the nominal diameter is more than twice the tool diameter; enter the roughing diameter Q342</source>
        <translation>cykl {1}: średnica nominalna jest ponad dwa razy większa od średnicy narzędzia; podaj średnicę wstępnej obróbki Q342</translation>
    </message>
    <message>
        <source>cycle {1}: the infeed per helix Q334 must be greater than 0</source>
        <translation>cykl {1}: dosuw na linię śrubową Q334 musi być większy od 0</translation>
    </message>
    <message>
        <source>BORE MILLING</source>
        <translation>FREZOWANIE OTWORU</translation>
    </message>
    <message>
        <source>Select depth (0) or diameter (1)</source>
        <translation>Wybór głębokości (0) lub średnicy (1)</translation>
    </message>
    <message>
        <source>Countersink diameter (sign = direction)</source>
        <translation>Średnica pogłębienia (znak = kierunek)</translation>
    </message>
    <message>
        <source>CENTERING</source>
        <translation>NAKIEŁKOWANIE</translation>
    </message>
    <message>
        <source>Direction of rotation for entry and exit (3 M3, 4 M4, 5 stationary)</source>
        <translation>Kierunek obrotów przy wejściu i wyjściu (3 M3, 4 M4, 5 stop)</translation>
    </message>
    <message>
        <source>Spindle speed for entry and exit</source>
        <translation>Prędkość obrotowa wrzeciona przy wejściu i wyjściu</translation>
    </message>
    <message>
        <source>Spindle speed for drilling</source>
        <translation>Prędkość obrotowa wrzeciona przy wierceniu</translation>
    </message>
    <message>
        <source>M function for coolant on (0: none)</source>
        <translation>Funkcja M włączenia chłodziwa (0: brak)</translation>
    </message>
    <message>
        <source>M function for coolant off (0: none)</source>
        <translation>Funkcja M wyłączenia chłodziwa (0: brak)</translation>
    </message>
    <message>
        <source>Dwell depth where the feed reduction begins (0: none)</source>
        <translation>Głębokość przerwy, od której zaczyna się redukcja posuwu (0: brak)</translation>
    </message>
    <message>
        <source>Feed rate factor beyond the dwell depth</source>
        <translation>Współczynnik posuwu poza głębokością przerwy</translation>
    </message>
    <message>
        <source>Maximum plunging depth</source>
        <translation>Maksymalna głębokość dosuwu</translation>
    </message>
    <message>
        <source>SINGLE-LIP DEEP-HOLE DRILLING</source>
        <translation>WIERCENIE GŁĘBOKICH OTWORÓW WIERTŁEM JEDNOOSTRZOWYM</translation>
    </message>
    <message>
        <source>cycle {1}: the depth Q{2} = {3} is positive (the machine parameter displayDepthErr forbids it)</source>
        <translation>cykl {1}: głębokość Q{2} = {3} jest dodatnia (parametr maszynowy displayDepthErr tego zabrania)</translation>
    </message>
    <message>
        <source>cycle {1}: more than {2} infeeds; increase the plunging depth</source>
        <translation>cykl {1}: ponad {2} dosuwów; zwiększ głębokość dosuwu</translation>
    </message>
    <message>
        <source>cycle {1} needs the point angle T-ANGLE of the tool in the tool table</source>
        <translation>cykl {1} potrzebuje kąta wierzchołkowego T-ANGLE narzędzia w tabeli narzędzi</translation>
    </message>
    <message>
        <source>cycle {1} needs more than {2} moves</source>
        <translation>cykl {1} potrzebuje ponad {2} ruchów</translation>
    </message>
    <message>
        <source>Path overlap factor</source>
        <translation>Współczynnik nakładania się torów</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 helical, 2 reciprocating)</source>
        <translation>Strategia wcięcia (0 pionowo, 1 po linii śrubowej, 2 ruchem wahadłowym)</translation>
    </message>
    <message>
        <source>Set-up clearance</source>
        <translation>Odstęp bezpieczeństwa</translation>
    </message>
    <message>
        <source>Clearance height (absolute)</source>
        <translation>Bezpieczna wysokość (absolutnie)</translation>
    </message>
    <message>
        <source>Direction of rotation (+1 climb, -1 up-cut)</source>
        <translation>Kierunek obrotu (+1 współbieżnie, -1 przeciwbieżnie)</translation>
    </message>
    <message>
        <source>Set-up clearance of the probe</source>
        <translation>Odstęp bezpieczeństwa sondy</translation>
    </message>
    <message>
        <source>Clearance height</source>
        <translation>Bezpieczna wysokość</translation>
    </message>
    <message>
        <source>Move to clearance height between points</source>
        <translation>Przejazd na bezpieczną wysokość między punktami</translation>
    </message>
    <message>
        <source>Height between pattern points: 2nd set-up clearance (1) or the position at the start (0)</source>
        <translation>Wysokość między punktami wzorca: 2. odstęp bezpieczeństwa (1) lub pozycja na starcie (0)</translation>
    </message>
    <message>
        <source>GENERAL</source>
        <translation>OGÓLNE</translation>
    </message>
    <message>
        <source>POCKET MILLING</source>
        <translation>FREZOWANIE KIESZENI</translation>
    </message>
    <message>
        <source>CONTOUR MILLING</source>
        <translation>FREZOWANIE KONTURU</translation>
    </message>
    <message>
        <source>PROBING</source>
        <translation>PRÓBKOWANIE</translation>
    </message>
    <message>
        <source>POSITIONING</source>
        <translation>POZYCJONOWANIE</translation>
    </message>
    <message>
        <source>Centre in the 1st axis</source>
        <translation>Środek w 1. osi</translation>
    </message>
    <message>
        <source>Centre in the 2nd axis</source>
        <translation>Środek w 2. osi</translation>
    </message>
    <message>
        <source>Pitch circle diameter</source>
        <translation>Średnica koła podziałowego</translation>
    </message>
    <message>
        <source>Starting angle</source>
        <translation>Kąt startu</translation>
    </message>
    <message>
        <source>Stopping angle</source>
        <translation>Kąt końcowy</translation>
    </message>
    <message>
        <source>Stepping angle (0: from start, stop and count)</source>
        <translation>Krok kąta (0: z kąta startu, końcowego i liczby)</translation>
    </message>
    <message>
        <source>Number of operations</source>
        <translation>Liczba obróbek</translation>
    </message>
    <message>
        <source>Move between operations at set-up clearance (0) or at the 2nd set-up clearance (1)</source>
        <translation>Przejazd między obróbkami na odstępie bezpieczeństwa (0) lub na 2. odstępie bezpieczeństwa (1)</translation>
    </message>
    <message>
        <source>Type of traverse: straight line (0) or arc on the pitch circle (1)</source>
        <translation>Rodzaj przejazdu: prosta (0) lub łuk na kole podziałowym (1)</translation>
    </message>
    <message>
        <source>cycle {1}: the stopping angle Q246 must differ from the starting angle Q245</source>
        <translation>cykl {1}: kąt końcowy Q246 musi różnić się od kąta startu Q245</translation>
    </message>
    <message>
        <source>POLAR PATTERN</source>
        <translation>WZÓR PUNKTÓW NA OKRĘGU</translation>
    </message>
    <message>
        <source>Starting point in the 1st axis</source>
        <translation>Punkt startu w 1. osi</translation>
    </message>
    <message>
        <source>Starting point in the 2nd axis</source>
        <translation>Punkt startu w 2. osi</translation>
    </message>
    <message>
        <source>Spacing in the 1st axis</source>
        <translation>Odstęp w 1. osi</translation>
    </message>
    <message>
        <source>Spacing in the 2nd axis</source>
        <translation>Odstęp w 2. osi</translation>
    </message>
    <message>
        <source>Number of columns</source>
        <translation>Liczba kolumn</translation>
    </message>
    <message>
        <source>Number of lines</source>
        <translation>Liczba wierszy</translation>
    </message>
    <message>
        <source>Angle of rotation about the starting point</source>
        <translation>Kąt obrotu wokół punktu startu</translation>
    </message>
    <message>
        <source>cycle {1}: more than {2} positions</source>
        <translation>cykl {1}: ponad {2} pozycji</translation>
    </message>
    <message>
        <source>CARTESIAN PATTERN</source>
        <translation>WZÓR PUNKTÓW NA LINIACH</translation>
    </message>
    <message>
        <source>PATTERN DEF: {1} must be a whole number from 1 to 99999</source>
        <translation>PATTERN DEF: {1} musi być liczbą całkowitą od 1 do 99999</translation>
    </message>
    <message>
        <source>PATTERN DEF: more than {1} positions</source>
        <translation>PATTERN DEF: ponad {1} pozycji</translation>
    </message>
    <message>
        <source>Engraving text</source>
        <translation>Tekst do grawerowania</translation>
    </message>
    <message>
        <source>Character height (0: scaled to the text length Q574)</source>
        <translation>Wysokość znaków (0: dopasowana do długości tekstu Q574)</translation>
    </message>
    <message>
        <source>Spacing factor between the characters (0: as the font)</source>
        <translation>Współczynnik odstępu między znakami (0: wg czcionki)</translation>
    </message>
    <message>
        <source>Font (without function)</source>
        <translation>Czcionka (bez funkcji)</translation>
    </message>
    <message>
        <source>Text on a line (0), an arc (1) or an arc, continuous (2)</source>
        <translation>Tekst na prostej (0), na łuku (1) lub na łuku, ciągle (2)</translation>
    </message>
    <message>
        <source>Angle of rotation (centre angle on an arc)</source>
        <translation>Kąt obrotu (kąt środkowy na łuku)</translation>
    </message>
    <message>
        <source>Radius of the arc the text is on</source>
        <translation>Promień łuku, na którym leży tekst</translation>
    </message>
    <message>
        <source>Reference of the text position (0-6)</source>
        <translation>Odniesienie położenia tekstu (0-6)</translation>
    </message>
    <message>
        <source>Maximum text length (0: no limit)</source>
        <translation>Maksymalna długość tekstu (0: bez ograniczenia)</translation>
    </message>
    <message>
        <source>ENGRAVING</source>
        <translation>GRAWEROWANIE</translation>
    </message>
    <message>
        <source>Strategy (0 meander outside, 1 meander on the edge, 2 line by line)</source>
        <translation>Strategia (0 meandrowo na zewnątrz, 1 meandrowo na krawędzi, 2 wierszami)</translation>
    </message>
    <message>
        <source>Starting point in the 3rd axis (surface)</source>
        <translation>Punkt startu w 3. osi (powierzchnia)</translation>
    </message>
    <message>
        <source>End point in the 3rd axis</source>
        <translation>Punkt końcowy w 3. osi</translation>
    </message>
    <message>
        <source>First side length (sign = direction)</source>
        <translation>Długość 1. boku (znak = kierunek)</translation>
    </message>
    <message>
        <source>Second side length (sign = direction)</source>
        <translation>Długość 2. boku (znak = kierunek)</translation>
    </message>
    <message>
        <source>Finishing allowance for the floor</source>
        <translation>Naddatek na obróbkę wykańczającą dna</translation>
    </message>
    <message>
        <source>Maximum path overlap factor</source>
        <translation>Maksymalny współczynnik nakładania się torów</translation>
    </message>
    <message>
        <source>Feed rate for finishing</source>
        <translation>Posuw obróbki wykańczającej</translation>
    </message>
    <message>
        <source>Lateral clearance to the workpiece</source>
        <translation>Odstęp boczny od obrabianego przedmiotu</translation>
    </message>
    <message>
        <source>cycle {1}: the starting point Q227 must be above the end point Q386</source>
        <translation>cykl {1}: punkt startu Q227 musi leżeć powyżej punktu końcowego Q386</translation>
    </message>
    <message>
        <source>cycle {1} needs a tool radius R greater than R2</source>
        <translation>cykl {1} potrzebuje promienia narzędzia R większego od R2</translation>
    </message>
    <message>
        <source>FACE MILLING</source>
        <translation>FREZOWANIE PŁASZCZYZN</translation>
    </message>
    <message>
        <source>cycle 225: with the character height Q513 = 0 the text length Q574 must be given</source>
        <translation>cykl 225: przy wysokości znaków Q513 = 0 należy podać długość tekstu Q574</translation>
    </message>
    <message>
        <source>cycle 225: the text has no length that Q574 could scale</source>
        <translation>cykl 225: tekst nie ma długości, którą Q574 mógłby skalować</translation>
    </message>
    <message>
        <source>cycle 225: the text is {1} mm long, longer than the maximum text length Q574 = {2}</source>
        <translation>cykl 225: tekst ma długość {1} mm, większą od maksymalnej długości tekstu Q574 = {2}</translation>
    </message>
    <message>
        <source>cycle 225: text on a circle needs the radius Q517</source>
        <translation>cykl 225: tekst na okręgu potrzebuje promienia Q517</translation>
    </message>
    <message>
        <source>cycle 225: the character &apos;{1}&apos; cannot be engraved</source>
        <translation>cykl 225: znaku &apos;{1}&apos; nie można wygrawerować</translation>
    </message>
    <message>
        <source>cycle 225: unknown formatting character &apos;\{1}&apos; in the text (write \\ for a backslash)</source>
        <translation>cykl 225: nieznany znak formatowania &apos;\{1}&apos; w tekście (napisz \\ dla ukośnika wstecznego)</translation>
    </message>
    <message>
        <source>cycle 225: &apos;%time{1}&apos; is not a date format (use %time00 to %time15)</source>
        <translation>cykl 225: &apos;%time{1}&apos; nie jest formatem daty (użyj %time00 do %time15)</translation>
    </message>
    <message>
        <source>cycle 225: &apos;%count&apos; needs the number of digits (1 to 9)</source>
        <translation>cykl 225: &apos;%count&apos; potrzebuje liczby cyfr (1 do 9)</translation>
    </message>
    <message>
        <source>cycle 225: unknown escape &apos;%{1}&apos; in the text (write %% for a percent sign)</source>
        <translation>cykl 225: nieznana sekwencja &apos;%{1}&apos; w tekście (napisz %% dla znaku procentu)</translation>
    </message>
    <message>
        <source>Dwell time</source>
        <translation>Czas przerwy</translation>
    </message>
    <message>
        <source>Program to call as a machining cycle</source>
        <translation>Program wywoływany jako cykl obróbki</translation>
    </message>
    <message>
        <source>Orientation angle of the spindle</source>
        <translation>Kąt orientacji wrzeciona</translation>
    </message>
    <message>
        <source>Tolerance (0: machine default)</source>
        <translation>Tolerancja (0: wartość domyślna maszyny)</translation>
    </message>
    <message>
        <source>Filter: finishing (0) or roughing (1)</source>
        <translation>Filtr: obróbka wykańczająca (0) lub zgrubna (1)</translation>
    </message>
    <message>
        <source>Tolerance of rotary axes (0: machine default)</source>
        <translation>Tolerancja osi obrotowych (0: wartość domyślna maszyny)</translation>
    </message>
    <message>
        <source>DWELL TIME</source>
        <translation>CZAS PRZERWY</translation>
    </message>
    <message>
        <source>PGM CALL</source>
        <translation>PGM CALL</translation>
    </message>
    <message>
        <source>ORIENTED SPINDLE STOP</source>
        <translation>ORIENTACJA WRZECIONA</translation>
    </message>
    <message>
        <source>TOLERANCE</source>
        <translation>TOLERANCJA</translation>
    </message>
    <message>
        <source>Total hole depth from the current position</source>
        <translation>Całkowita głębokość otworu od aktualnej pozycji</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch is 0</source>
        <translation>cykl {1}: skok gwintu wynosi 0</translation>
    </message>
    <message>
        <source>THREAD CUTTING</source>
        <translation>GWINTOWANIE</translation>
    </message>
    <message>
        <source>Feed rate for tapping (spindle speed x pitch)</source>
        <translation>Posuw gwintowania (prędkość obrotowa x skok)</translation>
    </message>
    <message>
        <source>cycle {1} needs the spindle running (M3 or M4)</source>
        <translation>cykl {1} wymaga obracającego się wrzeciona (M3 lub M4)</translation>
    </message>
    <message>
        <source>TAPPING WITH A FLOATING TAP HOLDER</source>
        <translation>GWINTOWANIE Z UCHWYTEM WYRÓWNAWCZYM</translation>
    </message>
    <message>
        <source>RIGID TAPPING</source>
        <translation>GWINTOWANIE BEZ UCHWYTU WYRÓWNAWCZEGO</translation>
    </message>
    <message>
        <source>Retraction for chip breaking in pitches (0: out of the hole)</source>
        <translation>Powrót przy łamaniu wióra w skokach gwintu (0: z otworu)</translation>
    </message>
    <message>
        <source>Spindle speed factor for retraction</source>
        <translation>Współczynnik prędkości obrotowej przy wycofaniu</translation>
    </message>
    <message>
        <source>TAPPING WITH CHIP BREAKING</source>
        <translation>GWINTOWANIE Z ŁAMANIEM WIÓRA</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch {2} differs from the pitch {3} of the tool in the tool table</source>
        <translation>cykl {1}: skok gwintu {2} różni się od skoku {3} narzędzia w tabeli narzędzi</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch Q{2} is 0</source>
        <translation>cykl {1}: skok gwintu Q{2} wynosi 0</translation>
    </message>
    <message>
        <source>THREAD MILLING</source>
        <translation>FREZOWANIE GWINTÓW</translation>
    </message>
    <message>
        <source>THREAD MILLING/COUNTERSINKING</source>
        <translation>FREZOWANIE GWINTÓW Z POGŁĘBIENIEM</translation>
    </message>
    <message>
        <source>THREAD DRILLING/MILLING</source>
        <translation>WIERCENIE I FREZOWANIE GWINTÓW</translation>
    </message>
    <message>
        <source>Countersink before (0) or after (1) the thread</source>
        <translation>Pogłębienie przed (0) lub po (1) gwincie</translation>
    </message>
    <message>
        <source>HELICAL THREAD DRILLING/MILLING</source>
        <translation>WIERCENIE I FREZOWANIE GWINTÓW PO LINII ŚRUBOWEJ</translation>
    </message>
    <message>
        <source>Countersinking offset at front: stud centre to tool centre</source>
        <translation>Przesunięcie pogłębienia czołowo: środek czopu do środka narzędzia</translation>
    </message>
    <message>
        <source>OUTSIDE THREAD MILLING</source>
        <translation>FREZOWANIE GWINTÓW ZEWNĘTRZNYCH</translation>
    </message>
    <message>
        <source>cycle {1}: the tool diameter {2} is too large for the nominal diameter {3}</source>
        <translation>cykl {1}: średnica narzędzia {2} jest za duża dla średnicy nominalnej {3}</translation>
    </message>
    <message>
        <source>cycle {1}: unexpected &apos;{2}&apos;</source>
        <translation>cykl {1}: nieoczekiwane &apos;{2}&apos;</translation>
    </message>
    <message>
        <source>cycle {1}: {2} needs a value</source>
        <translation>cykl {1}: {2} wymaga wartości</translation>
    </message>
    <message>
        <source>cycle {1}: scaling factor {2} = {3} is outside 0.000001 to 99.999999</source>
        <translation>cykl {1}: współczynnik skalowania {2} = {3} leży poza zakresem 0.000001 do 99.999999</translation>
    </message>
    <message>
        <source>Datum shift per axis (IX: incremental), or #n: datum number of the datum table</source>
        <translation>Przesunięcie punktu zerowego dla każdej osi (IX: przyrostowo) lub #n: numer punktu zerowego z tabeli punktów zerowych</translation>
    </message>
    <message>
        <source>Mirrored axes (none: mirroring off)</source>
        <translation>Osie odbite (brak: odbicie wyłączone)</translation>
    </message>
    <message>
        <source>Angle of rotation (IROT: incremental)</source>
        <translation>Kąt obrotu (IROT: przyrostowo)</translation>
    </message>
    <message>
        <source>Scaling factor</source>
        <translation>Współczynnik skalowania</translation>
    </message>
    <message>
        <source>Scaling factor per axis</source>
        <translation>Współczynnik skalowania dla każdej osi</translation>
    </message>
    <message>
        <source>Centre of the scaling per axis</source>
        <translation>Środek skalowania dla każdej osi</translation>
    </message>
    <message>
        <source>Number of the preset to activate</source>
        <translation>Numer aktywowanego punktu odniesienia</translation>
    </message>
    <message>
        <source>Tilt angles of the rotary axes</source>
        <translation>Kąty nachylenia osi obrotowych</translation>
    </message>
    <message>
        <source>Feed rate for automatic positioning</source>
        <translation>Posuw automatycznego pozycjonowania</translation>
    </message>
    <message>
        <source>Set-up clearance for automatic positioning</source>
        <translation>Odstęp bezpieczeństwa dla automatycznego pozycjonowania</translation>
    </message>
    <message>
        <source>cycle {1}: angle of rotation ROT = {2} is outside -360 to 360</source>
        <translation>cykl {1}: kąt obrotu ROT = {2} leży poza zakresem -360 do 360</translation>
    </message>
    <message>
        <source>DATUM SHIFT</source>
        <translation>PRZESUNIĘCIE PUNKTU ZEROWEGO</translation>
    </message>
    <message>
        <source>MIRROR IMAGE</source>
        <translation>ODBICIE LUSTRZANE</translation>
    </message>
    <message>
        <source>ROTATION</source>
        <translation>OBRÓT</translation>
    </message>
    <message>
        <source>SCALING</source>
        <translation>WSPÓŁCZYNNIK WYMIAROWY</translation>
    </message>
    <message>
        <source>AXIS-SPECIFIC SCALING</source>
        <translation>WSPÓŁCZYNNIK WYMIAROWY SPECYFICZNY DLA OSI</translation>
    </message>
    <message>
        <source>PRESETTING</source>
        <translation>WYZNACZENIE PUNKTU ODNIESIENIA</translation>
    </message>
    <message>
        <source>WORKING PLANE</source>
        <translation>PŁASZCZYZNA OBRÓBKI</translation>
    </message>
    <message>
        <source>the block is longer than 60000 characters</source>
        <translation>blok jest dłuższy niż 60000 znaków</translation>
    </message>
    <message>
        <source>empty block: a block needs at least a comment</source>
        <translation>pusty blok: blok wymaga co najmniej komentarza</translation>
    </message>
    <message>
        <source>a block has at most 3 skip marks</source>
        <translation>blok ma co najwyżej 3 znaki pominięcia</translation>
    </message>
    <message>
        <source>a block label cannot be a parameter</source>
        <translation>etykieta bloku nie może być parametrem</translation>
    </message>
    <message>
        <source>label number expected after N</source>
        <translation>po N oczekiwano numeru etykiety</translation>
    </message>
    <message>
        <source>a label has at most 8 digits (N0-N99999999)</source>
        <translation>etykieta ma co najwyżej 8 cyfr (N0-N99999999)</translation>
    </message>
    <message>
        <source>missing &apos;)&apos; at the end of the high-level block</source>
        <translation>brak &apos;)&apos; na końcu bloku wysokiego poziomu</translation>
    </message>
    <message>
        <source>repetition count expected after N</source>
        <translation>po N oczekiwano liczby powtórzeń</translation>
    </message>
    <message>
        <source>a repetition count has at most 4 digits (N0-N9999)</source>
        <translation>liczba powtórzeń ma co najwyżej 4 cyfry (N0-N9999)</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; at the end of the block</source>
        <translation>nieoczekiwane &apos;{1}&apos; na końcu bloku</translation>
    </message>
    <message>
        <source>expressions are not allowed in ISO blocks</source>
        <translation>wyrażenia nie są dozwolone w blokach ISO</translation>
    </message>
    <message>
        <source>parameter number expected after P</source>
        <translation>po P oczekiwano numeru parametru</translation>
    </message>
    <message>
        <source>number expected after the sign of {1}</source>
        <translation>po znaku {1} oczekiwano liczby</translation>
    </message>
    <message>
        <source>{1} cannot be negative</source>
        <translation>{1} nie może być ujemne</translation>
    </message>
    <message>
        <source>{1} value {2} is outside the format {3}.{4}</source>
        <translation>wartość {2} słowa {1} wykracza poza format {3}.{4}</translation>
    </message>
    <message>
        <source>{1} is outside the format {2}.{3}</source>
        <translation>{1} wykracza poza format {2}.{3}</translation>
    </message>
    <message>
        <source>{1} must be a whole number from {2} to {3}</source>
        <translation>{1} musi być liczbą całkowitą od {2} do {3}</translation>
    </message>
    <message>
        <source>{1} is programmed twice</source>
        <translation>{1} zaprogramowano dwukrotnie</translation>
    </message>
    <message>
        <source>&apos;{1}&apos;: words are written in upper case</source>
        <translation>&apos;{1}&apos;: słowa pisze się wielkimi literami</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos;</source>
        <translation>nieoczekiwane &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>G functions are written at the start of the block</source>
        <translation>funkcje G pisze się na początku bloku</translation>
    </message>
    <message>
        <source>too many G functions in one block</source>
        <translation>zbyt wiele funkcji G w jednym bloku</translation>
    </message>
    <message>
        <source>axis letters after G14, G16 or G74 take no value</source>
        <translation>litery osi po G14, G16 lub G74 nie przyjmują wartości</translation>
    </message>
    <message>
        <source>I is programmed more than twice</source>
        <translation>I zaprogramowano więcej niż dwukrotnie</translation>
    </message>
    <message>
        <source>at most 7 M functions in one block</source>
        <translation>co najwyżej 7 funkcji M w jednym bloku</translation>
    </message>
    <message>
        <source>E belongs to G51</source>
        <translation>E należy do G51</translation>
    </message>
    <message>
        <source>unknown word &apos;{1}&apos;</source>
        <translation>nieznane słowo &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 cannot be used in a thread</source>
        <translation>G36, G37, G38 i G39 nie mogą być użyte w gwincie</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 need a move in the plane</source>
        <translation>G36, G37, G38 i G39 wymagają ruchu w płaszczyźnie</translation>
    </message>
    <message>
        <source>the next block must be a contour element in the plane</source>
        <translation>następny blok musi być elementem konturu w płaszczyźnie</translation>
    </message>
    <message>
        <source>G37 needs a straight line (G00 or G01)</source>
        <translation>G37 wymaga prostej (G00 lub G01)</translation>
    </message>
    <message>
        <source>G37: the start point lies inside the entry circle</source>
        <translation>G37: punkt startu leży wewnątrz okręgu wejścia</translation>
    </message>
    <message>
        <source>G36: the rounding radius does not fit between the elements</source>
        <translation>G36: promień zaokrąglenia nie mieści się między elementami</translation>
    </message>
    <message>
        <source>G39 needs straight lines on both sides</source>
        <translation>G39 wymaga prostych po obu stronach</translation>
    </message>
    <message>
        <source>G39: the chamfer is longer than an adjacent line</source>
        <translation>G39: faza jest dłuższa od przyległej prostej</translation>
    </message>
    <message>
        <source>the block after G38 must be a straight line (G00 or G01)</source>
        <translation>blok po G38 musi być prostą (G00 lub G01)</translation>
    </message>
    <message>
        <source>G38: the end point lies inside the exit circle</source>
        <translation>G38: punkt końcowy leży wewnątrz okręgu wyjścia</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 need a following contour element</source>
        <translation>G36, G37, G38 i G39 wymagają następnego elementu konturu</translation>
    </message>
    <message>
        <source>division by zero</source>
        <translation>dzielenie przez zero</translation>
    </message>
    <message>
        <source>EXP: {1} to the power {2} has no value</source>
        <translation>EXP: {1} do potęgi {2} nie ma wartości</translation>
    </message>
    <message>
        <source>MOD by zero</source>
        <translation>MOD przez zero</translation>
    </message>
    <message>
        <source>&apos;)&apos; expected</source>
        <translation>oczekiwano &apos;)&apos;</translation>
    </message>
    <message>
        <source>a function argument needs parentheses unless it is a number</source>
        <translation>argument funkcji wymaga nawiasów, chyba że jest liczbą</translation>
    </message>
    <message>
        <source>{1}: {2} is outside its domain</source>
        <translation>{1}: {2} leży poza dziedziną</translation>
    </message>
    <message>
        <source>a hexadecimal constant has 1 to 8 digits</source>
        <translation>stała szesnastkowa ma od 1 do 8 cyfr</translation>
    </message>
    <message>
        <source>number expected</source>
        <translation>oczekiwano liczby</translation>
    </message>
    <message>
        <source>a constant has at most 6 integer and 5 decimal digits</source>
        <translation>stała ma co najwyżej 6 cyfr całkowitych i 5 dziesiętnych</translation>
    </message>
    <message>
        <source>an index must be a whole number, not {1}</source>
        <translation>indeks musi być liczbą całkowitą, nie {1}</translation>
    </message>
    <message>
        <source>number or (expression) expected</source>
        <translation>oczekiwano liczby lub (wyrażenia)</translation>
    </message>
    <message>
        <source>GPOS needs N&lt;block&gt;</source>
        <translation>GPOS wymaga N&lt;blok&gt;</translation>
    </message>
    <message>
        <source>GPOS needs P&lt;program&gt;</source>
        <translation>GPOS wymaga P&lt;program&gt;</translation>
    </message>
    <message>
        <source>{1} needs a number</source>
        <translation>{1} wymaga liczby</translation>
    </message>
    <message>
        <source>value expected</source>
        <translation>oczekiwano wartości</translation>
    </message>
    <message>
        <source>&apos;(&apos; expected</source>
        <translation>oczekiwano &apos;(&apos;</translation>
    </message>
    <message>
        <source>&apos;,&apos; expected</source>
        <translation>oczekiwano &apos;,&apos;</translation>
    </message>
    <message>
        <source>label N{1} is not defined in this program</source>
        <translation>etykieta N{1} nie jest zdefiniowana w tym programie</translation>
    </message>
    <message>
        <source>label N{1} is not defined in the program</source>
        <translation>etykieta N{1} nie jest zdefiniowana w programie</translation>
    </message>
    <message>
        <source>RPT: block N{1} comes before block N{2}</source>
        <translation>RPT: blok N{1} występuje przed blokiem N{2}</translation>
    </message>
    <message>
        <source>more than {1} nested levels</source>
        <translation>ponad {1} poziomów zagnieżdżenia</translation>
    </message>
    <message>
        <source>cannot read program {1}: {2}</source>
        <translation>nie można odczytać programu {1}: {2}</translation>
    </message>
    <message>
        <source>program {1} has errors</source>
        <translation>program {1} zawiera błędy</translation>
    </message>
    <message>
        <source>program {1} is not in the NC root</source>
        <translation>programu {1} nie ma w katalogu głównym NC</translation>
    </message>
    <message>
        <source>subroutine {1} is not defined</source>
        <translation>podprogram {1} nie jest zdefiniowany</translation>
    </message>
    <message>
        <source>subroutine {1} is defined in more than one program</source>
        <translation>podprogram {1} jest zdefiniowany w więcej niż jednym programie</translation>
    </message>
    <message>
        <source>the program with subroutine {1} has errors</source>
        <translation>program z podprogramem {1} zawiera błędy</translation>
    </message>
    <message>
        <source>error 1255: subroutine restricted to OEM programs</source>
        <translation>błąd 1255: podprogram zastrzeżony dla programów OEM</translation>
    </message>
    <message>
        <source>more than 6 nested levels of local parameters</source>
        <translation>ponad 6 poziomów zagnieżdżenia parametrów lokalnych</translation>
    </message>
    <message>
        <source>subroutine {1} has no RET</source>
        <translation>podprogram {1} nie ma RET</translation>
    </message>
    <message>
        <source>RET outside a subroutine</source>
        <translation>RET poza podprogramem</translation>
    </message>
    <message>
        <source>error 1064: program cannot be executed (MEXEC inside the modal program)</source>
        <translation>błąd 1064: programu nie można wykonać (MEXEC wewnątrz programu modalnego)</translation>
    </message>
    <message>
        <source>REPOS is only allowed in an interrupt subroutine</source>
        <translation>REPOS jest dozwolone tylko w podprogramie przerwania</translation>
    </message>
    <message>
        <source>REPOS failed</source>
        <translation>REPOS nie powiodło się</translation>
    </message>
    <message>
        <source>collision detection removed a loop of the compensated path</source>
        <translation>wykrywanie kolizji usunęło pętlę ze skorygowanego toru</translation>
    </message>
    <message>
        <source>the program ends before the last block of the RPT</source>
        <translation>program kończy się przed ostatnim blokiem RPT</translation>
    </message>
    <message>
        <source>the program ends inside a subroutine (RET missing)</source>
        <translation>program kończy się wewnątrz podprogramu (brak RET)</translation>
    </message>
    <message>
        <source>axis {1} is not available on this machine</source>
        <translation>oś {1} nie jest dostępna na tej maszynie</translation>
    </message>
    <message>
        <source>N{1}: only a motion block under a modal subroutine (MCALL, MEXEC) or a canned cycle can be repeated</source>
        <translation>N{1}: powtórzyć można tylko blok ruchu pod podprogramem modalnym (MCALL, MEXEC) lub cyklem stałym</translation>
    </message>
    <message>
        <source>incompatible G functions G51 and {1} (error 7)</source>
        <translation>niezgodne funkcje G: G51 i {1} (błąd 7)</translation>
    </message>
    <message>
        <source>G40, G41 and G42 need G00 or G01 active, not G02/G03</source>
        <translation>G40, G41 i G42 wymagają aktywnej G00 lub G01, nie G02/G03</translation>
    </message>
    <message>
        <source>radius compensation works in the ZX plane only (PLACOMP 0)</source>
        <translation>korekcja promienia działa tylko w płaszczyźnie ZX (PLACOMP 0)</translation>
    </message>
    <message>
        <source>{1} needs R greater than 0 right after it</source>
        <translation>{1} wymaga bezpośrednio po sobie R większego od 0</translation>
    </message>
    <message>
        <source>G37 needs R greater than 0 right after it</source>
        <translation>G37 wymaga bezpośrednio po sobie R większego od 0</translation>
    </message>
    <message>
        <source>G37 needs a straight line (G00 or G01), not G02/G03</source>
        <translation>G37 wymaga prostej (G00 lub G01), nie G02/G03</translation>
    </message>
    <message>
        <source>G06 belongs in a circular interpolation block</source>
        <translation>G06 należy do bloku interpolacji kołowej</translation>
    </message>
    <message>
        <source>G16 needs two axis letters: abscissa and ordinate</source>
        <translation>G16 wymaga dwóch liter osi: odciętej i rzędnej</translation>
    </message>
    <message>
        <source>G16 {1}{2}: only planes of two of the axes X, Y and Z are supported</source>
        <translation>G16 {1}{2}: obsługiwane są tylko płaszczyzny z dwóch osi X, Y i Z</translation>
    </message>
    <message>
        <source>the plane cannot change under radius compensation</source>
        <translation>płaszczyzna nie może zmieniać się przy aktywnej korekcji promienia</translation>
    </message>
    <message>
        <source>G51 needs E, the permitted contour error</source>
        <translation>G51 wymaga E, dopuszczalnego błędu konturu</translation>
    </message>
    <message>
        <source>G72 S: the scale factor must be greater than 0</source>
        <translation>G72 S: współczynnik skalowania musi być większy od 0</translation>
    </message>
    <message>
        <source>G72 needs S or axis factors</source>
        <translation>G72 wymaga S lub współczynników osi</translation>
    </message>
    <message>
        <source>G72: the scale factor of {1} must be greater than 0</source>
        <translation>G72: współczynnik skalowania {1} musi być większy od 0</translation>
    </message>
    <message>
        <source>{1} needs K, the zone number 1-4</source>
        <translation>{1} wymaga K, numeru strefy 1-4</translation>
    </message>
    <message>
        <source>G22 needs S0 (off), S1 (no entry) or S2 (no exit)</source>
        <translation>G22 wymaga S0 (wył.), S1 (zakaz wjazdu) lub S2 (zakaz wyjazdu)</translation>
    </message>
    <message>
        <source>G74 alone runs the subroutine of REFPSUB, which is not set</source>
        <translation>samo G74 wykonuje podprogram z REFPSUB, który nie jest ustawiony</translation>
    </message>
    <message>
        <source>G159 needs N1-N20</source>
        <translation>G159 wymaga N1-N20</translation>
    </message>
    <message>
        <source>G96 needs S: no cutting speed was programmed before</source>
        <translation>G96 wymaga S: wcześniej nie zaprogramowano prędkości skrawania</translation>
    </message>
    <message>
        <source>G96 needs a spindle gear range (M41-M44) first</source>
        <translation>G96 wymaga najpierw zakresu biegów wrzeciona (M41-M44)</translation>
    </message>
    <message>
        <source>S{1} is above the spindle limit of {2} rpm</source>
        <translation>S{1} przekracza limit wrzeciona {2} obr/min</translation>
    </message>
    <message>
        <source>M{1} has a subroutine: it must be alone in its block</source>
        <translation>M{1} ma podprogram: musi stać sama w bloku</translation>
    </message>
    <message>
        <source>polar coordinates (R, Q) and Cartesian coordinates of the plane in one block</source>
        <translation>współrzędne biegunowe (R, Q) i kartezjańskie współrzędne płaszczyzny w jednym bloku</translation>
    </message>
    <message>
        <source>the polar radius becomes negative</source>
        <translation>promień biegunowy staje się ujemny</translation>
    </message>
    <message>
        <source>an angle Q with both coordinates of the plane</source>
        <translation>kąt Q z obiema współrzędnymi płaszczyzny</translation>
    </message>
    <message>
        <source>angle Q {1}: the path cannot reach that abscissa</source>
        <translation>kąt Q {1}: tor nie może osiągnąć tej odciętej</translation>
    </message>
    <message>
        <source>angle Q {1}: the path cannot reach that ordinate</source>
        <translation>kąt Q {1}: tor nie może osiągnąć tej rzędnej</translation>
    </message>
    <message>
        <source>J is the centre of the Y axis: the ZX plane uses I and K</source>
        <translation>J to środek w osi Y: płaszczyzna ZX używa I i K</translation>
    </message>
    <message>
        <source>G08 needs a previous path in the plane to be tangent to</source>
        <translation>G08 wymaga poprzedniego toru w płaszczyźnie, do którego ma być styczny</translation>
    </message>
    <message>
        <source>G08 cannot program a full circle</source>
        <translation>G08 nie może programować pełnego okręgu</translation>
    </message>
    <message>
        <source>G08: the end point lies on the tangent of the previous path</source>
        <translation>G08: punkt końcowy leży na stycznej poprzedniego toru</translation>
    </message>
    <message>
        <source>G09 cannot program a full circle</source>
        <translation>G09 nie może programować pełnego okręgu</translation>
    </message>
    <message>
        <source>G09: the three points lie on a line</source>
        <translation>G09: trzy punkty leżą na jednej prostej</translation>
    </message>
    <message>
        <source>a full circle cannot be programmed with R</source>
        <translation>pełnego okręgu nie można programować z R</translation>
    </message>
    <message>
        <source>the arc radius R is too small for the end point</source>
        <translation>promień łuku R jest za mały dla punktu końcowego</translation>
    </message>
    <message>
        <source>the start and end radii differ by {1} mm (more than CIRINERR)</source>
        <translation>promienie na początku i końcu różnią się o {1} mm (więcej niż CIRINERR)</translation>
    </message>
    <message>
        <source>the arc has no radius</source>
        <translation>łuk nie ma promienia</translation>
    </message>
    <message>
        <source>arc centre or radius beyond 214748.3647 mm</source>
        <translation>środek lub promień łuku powyżej 214748.3647 mm</translation>
    </message>
    <message>
        <source>Q (spindle angle) needs M19TYPE = 1</source>
        <translation>Q (kąt wrzeciona) wymaga M19TYPE = 1</translation>
    </message>
    <message>
        <source>only the first thread of a joined chain may have Q</source>
        <translation>tylko pierwszy gwint połączonego łańcucha może mieć Q</translation>
    </message>
    <message>
        <source>Q must be within +-359.9999 degrees</source>
        <translation>Q musi mieścić się w +-359.9999 stopni</translation>
    </message>
    <message>
        <source>a thread needs its pitch L</source>
        <translation>gwint wymaga skoku L</translation>
    </message>
    <message>
        <source>two variable-pitch threads cannot be joined; end one with G34 L0 K0</source>
        <translation>dwóch gwintów o zmiennym skoku nie można łączyć; zakończ jeden przez G34 L0 K0</translation>
    </message>
    <message>
        <source>G34 joined to G33 must start with the pitch of the G33</source>
        <translation>G34 połączone z G33 musi zaczynać się ze skokiem G33</translation>
    </message>
    <message>
        <source>after G34 a constant pitch is programmed with G34 L0 K0</source>
        <translation>po G34 stały skok programuje się przez G34 L0 K0</translation>
    </message>
    <message>
        <source>the thread pitch must be greater than 0</source>
        <translation>skok gwintu musi być większy od 0</translation>
    </message>
    <message>
        <source>the variable pitch reaches zero before the end point</source>
        <translation>zmienny skok osiąga zero przed punktem końcowym</translation>
    </message>
    <message>
        <source>G53 works with G00 and G01 moves only</source>
        <translation>G53 działa tylko z ruchami G00 i G01</translation>
    </message>
    <message>
        <source>G52 moves one axis</source>
        <translation>G52 przesuwa jedną oś</translation>
    </message>
    <message>
        <source>no tool offset table: offset D{1} and the following ones are all zero</source>
        <translation>brak tabeli korekcji narzędzi: korekcja D{1} i następne są zerowe</translation>
    </message>
    <message>
        <source>the header should be %comment,attributes, (two commas)</source>
        <translation>nagłówek powinien mieć postać %komentarz,atrybuty, (dwa przecinki)</translation>
    </message>
    <message>
        <source>the program comment has more than 20 characters</source>
        <translation>komentarz programu ma ponad 20 znaków</translation>
    </message>
    <message>
        <source>words out of the order G, coordinates, F, S, T, D, M</source>
        <translation>słowa w kolejności innej niż G, współrzędne, F, S, T, D, M</translation>
    </message>
    <message>
        <source>subroutine {1} starts before subroutine {2} has its RET</source>
        <translation>podprogram {1} zaczyna się, zanim podprogram {2} ma swoje RET</translation>
    </message>
    <message>
        <source>error 63: program subroutine numbers from 1 to 9999 (10000-20000 only in OEM programs)</source>
        <translation>błąd 63: numery podprogramów od 1 do 9999 (10000-20000 tylko w programach OEM)</translation>
    </message>
    <message>
        <source>subroutine {1} is defined twice</source>
        <translation>podprogram {1} jest zdefiniowany dwukrotnie</translation>
    </message>
    <message>
        <source>programs on a PC over DNC are not available; the program cannot run past this block</source>
        <translation>programy na PC przez DNC nie są dostępne; program nie może wykonać się poza ten blok</translation>
    </message>
    <message>
        <source>label N{1} is used more than once; jumps go to the first one</source>
        <translation>etykieta N{1} jest użyta więcej niż raz; skoki prowadzą do pierwszej</translation>
    </message>
    <message>
        <source>incompatible G functions</source>
        <translation>niezgodne funkcje G</translation>
    </message>
    <message>
        <source>program subroutine number from 1 to 9999</source>
        <translation>numer podprogramu od 1 do 9999</translation>
    </message>
    <message>
        <source>the S that changes the gear range must be alone in its block</source>
        <translation>S zmieniające zakres biegów musi stać samo w bloku</translation>
    </message>
    <message>
        <source>program cannot be executed</source>
        <translation>programu nie można wykonać</translation>
    </message>
    <message>
        <source>subroutine restricted to OEM program</source>
        <translation>podprogram zastrzeżony dla programu OEM</translation>
    </message>
    <message>
        <source>{1}</source>
        <translation>{1}</translation>
    </message>
    <message>
        <source>error {1}</source>
        <translation>błąd {1}</translation>
    </message>
    <message>
        <source>error {1}: {2}</source>
        <translation>błąd {1}: {2}</translation>
    </message>
    <message>
        <source>DGWZ: Z minimum &lt; Z maximum and 0 &lt;= inner &lt; outer</source>
        <translation>DGWZ: Z minimum &lt; Z maksimum i 0 &lt;= wewnętrzna &lt; zewnętrzna</translation>
    </message>
    <message>
        <source>program {1} exists: OPEN needs A (append) or D (delete)</source>
        <translation>program {1} istnieje: OPEN wymaga A (dopisz) lub D (usuń)</translation>
    </message>
    <message>
        <source>program {1} is running: it cannot be opened</source>
        <translation>program {1} jest wykonywany: nie można go otworzyć</translation>
    </message>
    <message>
        <source>WRITE needs a program opened with OPEN</source>
        <translation>WRITE wymaga programu otwartego przez OPEN</translation>
    </message>
    <message>
        <source>GPOS: program {1} has no block N{2}</source>
        <translation>GPOS: program {1} nie ma bloku N{2}</translation>
    </message>
    <message>
        <source>GPOS: block not found</source>
        <translation>GPOS: nie znaleziono bloku</translation>
    </message>
    <message>
        <source>{1} is not available on the simulated machine</source>
        <translation>{1} nie jest dostępne na symulowanej maszynie</translation>
    </message>
    <message>
        <source>{1} cannot be read from a part program (PLC or DNC only)</source>
        <translation>{1} nie może być odczytane z programu obróbki (tylko PLC lub DNC)</translation>
    </message>
    <message>
        <source>{1}: the simulated machine has no tool magazine</source>
        <translation>{1}: symulowana maszyna nie ma magazynu narzędzi</translation>
    </message>
    <message>
        <source>{1}: offsets are numbered 0-255</source>
        <translation>{1}: korekcje mają numery 0-255</translation>
    </message>
    <message>
        <source>{1}: zero offsets are 54-59 and 1-20</source>
        <translation>{1}: przesunięcia punktu zerowego to 54-59 i 1-20</translation>
    </message>
    <message>
        <source>NBTOOL can only be read in the tool change subroutine</source>
        <translation>NBTOOL można odczytać tylko w podprogramie wymiany narzędzia</translation>
    </message>
    <message>
        <source>MS{1}: the state is kept for M00-M06, M08, M09, M19, M30 and M41-M44</source>
        <translation>MS{1}: stan jest przechowywany dla M00-M06, M08, M09, M19, M30 i M41-M44</translation>
    </message>
    <message>
        <source>{1}: outputs 1-8</source>
        <translation>{1}: wyjścia 1-8</translation>
    </message>
    <message>
        <source>{1} is read-only in a part program</source>
        <translation>{1} jest tylko do odczytu w programie obróbki</translation>
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
        <translation>{1}: korekcje to D1-D255, a F to 0-9</translation>
    </message>
    <message>
        <source>{1}: value out of range</source>
        <translation>{1}: wartość poza zakresem</translation>
    </message>
    <message>
        <source>KEY can only be written in a customisation program</source>
        <translation>KEY można zapisać tylko w programie dostosowania</translation>
    </message>
    <message>
        <source>KEYSRC can only be changed while it is 0</source>
        <translation>KEYSRC można zmienić tylko, gdy wynosi 0</translation>
    </message>
    <message>
        <source>{1}: free outputs 1-4, -10 to 10 V</source>
        <translation>{1}: wolne wyjścia 1-4, -10 do 10 V</translation>
    </message>
    <message>
        <source>rapid positioning</source>
        <translation>pozycjonowanie szybkie</translation>
    </message>
    <message>
        <source>linear interpolation</source>
        <translation>interpolacja liniowa</translation>
    </message>
    <message>
        <source>circular interpolation clockwise</source>
        <translation>interpolacja kołowa zgodnie z ruchem wskazówek zegara</translation>
    </message>
    <message>
        <source>circular interpolation counter-clockwise</source>
        <translation>interpolacja kołowa przeciwnie do ruchu wskazówek zegara</translation>
    </message>
    <message>
        <source>dwell / stop block preparation</source>
        <translation>przerwa / zatrzymanie przygotowania bloków</translation>
    </message>
    <message>
        <source>round corner</source>
        <translation>zaokrąglony narożnik</translation>
    </message>
    <message>
        <source>arc centre in absolute coordinates</source>
        <translation>środek łuku we współrzędnych absolutnych</translation>
    </message>
    <message>
        <source>sharp corner</source>
        <translation>ostry narożnik</translation>
    </message>
    <message>
        <source>arc tangent to the previous path</source>
        <translation>łuk styczny do poprzedniego toru</translation>
    </message>
    <message>
        <source>arc through three points</source>
        <translation>łuk przez trzy punkty</translation>
    </message>
    <message>
        <source>mirror image off</source>
        <translation>odbicie lustrzane wył.</translation>
    </message>
    <message>
        <source>mirror image in X</source>
        <translation>odbicie lustrzane w X</translation>
    </message>
    <message>
        <source>mirror image in Y</source>
        <translation>odbicie lustrzane w Y</translation>
    </message>
    <message>
        <source>mirror image in Z</source>
        <translation>odbicie lustrzane w Z</translation>
    </message>
    <message>
        <source>mirror image in the programmed axes</source>
        <translation>odbicie lustrzane w zaprogramowanych osiach</translation>
    </message>
    <message>
        <source>main plane by two axes</source>
        <translation>płaszczyzna główna przez dwie osie</translation>
    </message>
    <message>
        <source>main plane XY</source>
        <translation>płaszczyzna główna XY</translation>
    </message>
    <message>
        <source>main plane ZX</source>
        <translation>płaszczyzna główna ZX</translation>
    </message>
    <message>
        <source>main plane YZ</source>
        <translation>płaszczyzna główna YZ</translation>
    </message>
    <message>
        <source>work zone lower limits</source>
        <translation>dolne granice strefy roboczej</translation>
    </message>
    <message>
        <source>work zone upper limits</source>
        <translation>górne granice strefy roboczej</translation>
    </message>
    <message>
        <source>work zone enable/disable</source>
        <translation>włączenie/wyłączenie strefy roboczej</translation>
    </message>
    <message>
        <source>feed as inverse of time</source>
        <translation>posuw jako odwrotność czasu</translation>
    </message>
    <message>
        <source>electronic threading</source>
        <translation>gwintowanie elektroniczne</translation>
    </message>
    <message>
        <source>variable-pitch threading</source>
        <translation>gwintowanie o zmiennym skoku</translation>
    </message>
    <message>
        <source>corner rounding</source>
        <translation>zaokrąglanie narożników</translation>
    </message>
    <message>
        <source>tangential entry</source>
        <translation>wejście styczne</translation>
    </message>
    <message>
        <source>tangential exit</source>
        <translation>wyjście styczne</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>faza</translation>
    </message>
    <message>
        <source>radius compensation off</source>
        <translation>korekcja promienia wył.</translation>
    </message>
    <message>
        <source>radius compensation left</source>
        <translation>korekcja promienia z lewej</translation>
    </message>
    <message>
        <source>radius compensation right</source>
        <translation>korekcja promienia z prawej</translation>
    </message>
    <message>
        <source>inclined-axis transformation</source>
        <translation>transformacja osi nachylonej</translation>
    </message>
    <message>
        <source>controlled round corner</source>
        <translation>kontrolowany zaokrąglony narożnik</translation>
    </message>
    <message>
        <source>look-ahead</source>
        <translation>przetwarzanie z wyprzedzeniem (look-ahead)</translation>
    </message>
    <message>
        <source>move to hard stop</source>
        <translation>przejazd do zderzaka</translation>
    </message>
    <message>
        <source>coordinates from machine zero</source>
        <translation>współrzędne od zera maszyny</translation>
    </message>
    <message>
        <source>absolute zero offset 1</source>
        <translation>absolutne przesunięcie punktu zerowego 1</translation>
    </message>
    <message>
        <source>absolute zero offset 2</source>
        <translation>absolutne przesunięcie punktu zerowego 2</translation>
    </message>
    <message>
        <source>absolute zero offset 3</source>
        <translation>absolutne przesunięcie punktu zerowego 3</translation>
    </message>
    <message>
        <source>absolute zero offset 4</source>
        <translation>absolutne przesunięcie punktu zerowego 4</translation>
    </message>
    <message>
        <source>additive zero offset 1</source>
        <translation>addytywne przesunięcie punktu zerowego 1</translation>
    </message>
    <message>
        <source>additive zero offset 2</source>
        <translation>addytywne przesunięcie punktu zerowego 2</translation>
    </message>
    <message>
        <source>pattern repeat cycle</source>
        <translation>cykl powtarzania profilu</translation>
    </message>
    <message>
        <source>stock removal cycle along X</source>
        <translation>cykl skrawania wzdłuż X</translation>
    </message>
    <message>
        <source>stock removal cycle along Z</source>
        <translation>cykl skrawania wzdłuż Z</translation>
    </message>
    <message>
        <source>programming in inches</source>
        <translation>programowanie w calach</translation>
    </message>
    <message>
        <source>programming in millimetres</source>
        <translation>programowanie w milimetrach</translation>
    </message>
    <message>
        <source>scaling factor</source>
        <translation>współczynnik skalowania</translation>
    </message>
    <message>
        <source>machine reference search</source>
        <translation>szukanie punktu referencyjnego maszyny</translation>
    </message>
    <message>
        <source>probing move until touching</source>
        <translation>ruch próbkowania do zetknięcia</translation>
    </message>
    <message>
        <source>probing move until no longer touching</source>
        <translation>ruch próbkowania do utraty styku</translation>
    </message>
    <message>
        <source>turning cycle, straight sections</source>
        <translation>cykl toczenia, odcinki proste</translation>
    </message>
    <message>
        <source>facing cycle, straight sections</source>
        <translation>cykl planowania, odcinki proste</translation>
    </message>
    <message>
        <source>drilling cycle</source>
        <translation>cykl wiercenia</translation>
    </message>
    <message>
        <source>turning cycle, curved sections</source>
        <translation>cykl toczenia, odcinki łukowe</translation>
    </message>
    <message>
        <source>facing cycle, curved sections</source>
        <translation>cykl planowania, odcinki łukowe</translation>
    </message>
    <message>
        <source>longitudinal threading cycle</source>
        <translation>cykl gwintowania wzdłużnego</translation>
    </message>
    <message>
        <source>face threading cycle</source>
        <translation>cykl gwintowania czołowego</translation>
    </message>
    <message>
        <source>grooving cycle along X</source>
        <translation>cykl toczenia rowków wzdłuż X</translation>
    </message>
    <message>
        <source>grooving cycle along Z</source>
        <translation>cykl toczenia rowków wzdłuż Z</translation>
    </message>
    <message>
        <source>absolute programming</source>
        <translation>programowanie absolutne</translation>
    </message>
    <message>
        <source>incremental programming</source>
        <translation>programowanie przyrostowe</translation>
    </message>
    <message>
        <source>coordinate preset / spindle speed limit</source>
        <translation>ustawienie współrzędnych / ograniczenie prędkości obrotowej wrzeciona</translation>
    </message>
    <message>
        <source>polar origin preset</source>
        <translation>ustawienie początku układu biegunowego</translation>
    </message>
    <message>
        <source>feed per minute</source>
        <translation>posuw na minutę</translation>
    </message>
    <message>
        <source>feed per revolution</source>
        <translation>posuw na obrót</translation>
    </message>
    <message>
        <source>constant surface speed</source>
        <translation>stała prędkość skrawania</translation>
    </message>
    <message>
        <source>spindle speed in rpm</source>
        <translation>prędkość obrotowa wrzeciona w obr/min</translation>
    </message>
    <message>
        <source>X in diameter</source>
        <translation>X jako średnica</translation>
    </message>
    <message>
        <source>X in radius</source>
        <translation>X jako promień</translation>
    </message>
    <message>
        <source>absolute zero offset N1-N20</source>
        <translation>absolutne przesunięcie punktu zerowego N1-N20</translation>
    </message>
    <message>
        <source>axis retraction when threading stops</source>
        <translation>wycofanie osi przy zatrzymaniu gwintowania</translation>
    </message>
    <message>
        <source>{1} does not exist on the 8035 T</source>
        <translation>{1} nie istnieje w 8035 T</translation>
    </message>
    <message>
        <source>{1} ({2}) is not supported</source>
        <translation>{1} ({2}) nie jest obsługiwane</translation>
    </message>
    <message>
        <source>incompatible G functions {1} and {2} (error 7)</source>
        <translation>niezgodne funkcje G {1} i {2} (błąd 7)</translation>
    </message>
    <message>
        <source>{1} must be alone in its block</source>
        <translation>{1} musi stać samo w bloku</translation>
    </message>
    <message>
        <source>tool radius too large</source>
        <translation>za duży promień narzędzia</translation>
    </message>
    <message>
        <source>tool radius too large: the offset swallows this element</source>
        <translation>za duży promień narzędzia: korekcja pochłania ten element</translation>
    </message>
    <message>
        <source>tool radius too large for this arc</source>
        <translation>za duży promień narzędzia dla tego łuku</translation>
    </message>
    <message>
        <source>G40 needs a straight line (G00 or G01)</source>
        <translation>G40 wymaga prostej (G00 lub G01)</translation>
    </message>
    <message>
        <source>48 blocks without motion in the plane under radius compensation</source>
        <translation>48 bloków bez ruchu w płaszczyźnie przy korekcji promienia</translation>
    </message>
    <message>
        <source>the move violates work zone 1</source>
        <translation>ruch narusza strefę roboczą 1</translation>
    </message>
    <message>
        <source>the move violates work zone 2</source>
        <translation>ruch narusza strefę roboczą 2</translation>
    </message>
    <message>
        <source>the move violates work zone 3</source>
        <translation>ruch narusza strefę roboczą 3</translation>
    </message>
    <message>
        <source>the move violates work zone 4</source>
        <translation>ruch narusza strefę roboczą 4</translation>
    </message>
    <message>
        <source>the move violates work zone 5</source>
        <translation>ruch narusza strefę roboczą 5</translation>
    </message>
    <message>
        <source>an arc cannot be scaled differently along the two axes of its plane (G72)</source>
        <translation>łuku nie można skalować różnie w dwóch osiach jego płaszczyzny (G72)</translation>
    </message>
    <message>
        <source>P{1}: an interrupt subroutine may only use global parameters</source>
        <translation>P{1}: podprogram przerwania może używać tylko parametrów globalnych</translation>
    </message>
    <message>
        <source>P{1}: OEM parameters are only for programs with the O attribute</source>
        <translation>P{1}: parametry OEM są tylko dla programów z atrybutem O</translation>
    </message>
    <message>
        <source>P{1} does not exist (P0-P25, P100-P299, P1000-P1255, P2000-P2255)</source>
        <translation>P{1} nie istnieje (P0-P25, P100-P299, P1000-P1255, P2000-P2255)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; expected</source>
        <translation>oczekiwano &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>{1} must be a whole number from {2} to {3}, not {4}</source>
        <translation>{1} musi być liczbą całkowitą od {2} do {3}, nie {4}</translation>
    </message>
    <message>
        <source>a label has at most 8 digits</source>
        <translation>etykieta ma co najwyżej 8 cyfr</translation>
    </message>
    <message>
        <source>text in quotes expected</source>
        <translation>oczekiwano tekstu w cudzysłowie</translation>
    </message>
    <message>
        <source>missing closing quote</source>
        <translation>brak zamykającego cudzysłowu</translation>
    </message>
    <message>
        <source>empty high-level block</source>
        <translation>pusty blok wysokiego poziomu</translation>
    </message>
    <message>
        <source>IF cannot be nested</source>
        <translation>IF nie może być zagnieżdżone</translation>
    </message>
    <message>
        <source>SUB cannot be the action of an IF</source>
        <translation>SUB nie może być akcją IF</translation>
    </message>
    <message>
        <source>subroutine number 0-20000 expected after SUB</source>
        <translation>po SUB oczekiwano numeru podprogramu 0-20000</translation>
    </message>
    <message>
        <source>at most 26 assignments to different targets</source>
        <translation>co najwyżej 26 przypisań do różnych celów</translation>
    </message>
    <message>
        <source>parameter or variable expected</source>
        <translation>oczekiwano parametru lub zmiennej</translation>
    </message>
    <message>
        <source>a subroutine call passes local parameters (P0-P25, A-Z)</source>
        <translation>wywołanie podprogramu przekazuje parametry lokalne (P0-P25, A-Z)</translation>
    </message>
    <message>
        <source>&apos;=&apos; expected</source>
        <translation>oczekiwano &apos;=&apos;</translation>
    </message>
    <message>
        <source>a subroutine call passes local parameters P0-P25, not P{1}</source>
        <translation>wywołanie podprogramu przekazuje parametry lokalne P0-P25, nie P{1}</translation>
    </message>
    <message>
        <source>error number expected</source>
        <translation>oczekiwano numeru błędu</translation>
    </message>
    <message>
        <source>ERROR takes a number, a parameter P0-P299 or a text</source>
        <translation>ERROR przyjmuje liczbę, parametr P0-P299 lub tekst</translation>
    </message>
    <message>
        <source>CALL passes no parameters: use PCALL or MCALL</source>
        <translation>CALL nie przekazuje parametrów: użyj PCALL lub MCALL</translation>
    </message>
    <message>
        <source>at most 26 parameters</source>
        <translation>co najwyżej 26 parametrów</translation>
    </message>
    <message>
        <source>programs on a PC over DNC are not available: only programs in the NC root</source>
        <translation>programy na PC przez DNC nie są dostępne: tylko programy w katalogu głównym NC</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in {2}</source>
        <translation>nieoczekiwane &apos;{1}&apos; w {2}</translation>
    </message>
    <message>
        <source>axis letter expected in REPOS</source>
        <translation>w REPOS oczekiwano litery osi</translation>
    </message>
    <message>
        <source>too many axes in REPOS</source>
        <translation>zbyt wiele osi w REPOS</translation>
    </message>
    <message>
        <source>INPUT expected</source>
        <translation>oczekiwano INPUT</translation>
    </message>
    <message>
        <source>DW expected</source>
        <translation>oczekiwano DW</translation>
    </message>
    <message>
        <source>SK expected</source>
        <translation>oczekiwano SK</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a row key</source>
        <translation>&apos;{1}&apos; nie jest kluczem wiersza</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a field (letters and a number)</source>
        <translation>&apos;{1}&apos; nie jest polem (litery i liczba)</translation>
    </message>
    <message>
        <source>row {1} appears twice</source>
        <translation>wiersz {1} występuje dwukrotnie</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a tool offset (D0-D255)</source>
        <translation>&apos;{1}&apos; nie jest korekcją narzędzia (D0-D255)</translation>
    </message>
    <message>
        <source>unknown field &apos;{1}&apos; (X Z F R I K)</source>
        <translation>nieznane pole &apos;{1}&apos; (X Z F R I K)</translation>
    </message>
    <message>
        <source>the location code F must be a whole number 0-9</source>
        <translation>kod położenia F musi być liczbą całkowitą 0-9</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a tool (T&lt;number&gt;)</source>
        <translation>&apos;{1}&apos; nie jest narzędziem (T&lt;numer&gt;)</translation>
    </message>
    <message>
        <source>unknown field &apos;{1}&apos; (D FAM NLIFE RLIFE NOSEA NOSEW CUTA)</source>
        <translation>nieznane pole &apos;{1}&apos; (D FAM NLIFE RLIFE NOSEA NOSEW CUTA)</translation>
    </message>
    <message>
        <source>{1} must be a whole number 0-255</source>
        <translation>{1} musi być liczbą całkowitą 0-255</translation>
    </message>
    <message>
        <source>G159 selects offsets N1-N20</source>
        <translation>G159 wybiera przesunięcia N1-N20</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; cannot be part of the ACTIVE selection</source>
        <translation>&apos;{1}&apos; nie może być częścią wyboru ACTIVE</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a zero offset (G54-G59, G159N7-G159N20, PLC, ACTIVE)</source>
        <translation>&apos;{1}&apos; nie jest przesunięciem punktu zerowego (G54-G59, G159N7-G159N20, PLC, ACTIVE)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not an axis</source>
        <translation>&apos;{1}&apos; nie jest osią</translation>
    </message>
    <message>
        <source>the feed rate must not be negative</source>
        <translation>posuw nie może być ujemny</translation>
    </message>
    <message>
        <source>M function number expected</source>
        <translation>oczekiwano numeru funkcji M</translation>
    </message>
    <message>
        <source>too many M functions in one block</source>
        <translation>zbyt wiele funkcji M w jednym bloku</translation>
    </message>
    <message>
        <source>axis {1} is programmed twice</source>
        <translation>oś {1} zaprogramowano dwukrotnie</translation>
    </message>
    <message>
        <source>DR+ or DR- expected</source>
        <translation>oczekiwano DR+ lub DR-</translation>
    </message>
    <message>
        <source>CR needs a radius R</source>
        <translation>CR wymaga promienia R</translation>
    </message>
    <message>
        <source>the rounding radius must be positive</source>
        <translation>promień zaokrąglenia musi być dodatni</translation>
    </message>
    <message>
        <source>the chamfer length must be positive</source>
        <translation>długość fazy musi być dodatnia</translation>
    </message>
    <message>
        <source>FMAX is not allowed here</source>
        <translation>FMAX nie jest tu dozwolone</translation>
    </message>
    <message>
        <source>LT, LN, CT or LCT expected after {1}</source>
        <translation>po {1} oczekiwano LT, LN, CT lub LCT</translation>
    </message>
    <message>
        <source>REP must be between 0 and 65534</source>
        <translation>REP musi leżeć między 0 a 65534</translation>
    </message>
    <message>
        <source>program name expected</source>
        <translation>oczekiwano nazwy programu</translation>
    </message>
    <message>
        <source>LBL or PGM expected after CALL</source>
        <translation>po CALL oczekiwano LBL lub PGM</translation>
    </message>
    <message>
        <source>tool number out of range</source>
        <translation>numer narzędzia poza zakresem</translation>
    </message>
    <message>
        <source>the spindle speed must not be negative</source>
        <translation>prędkość obrotowa wrzeciona nie może być ujemna</translation>
    </message>
    <message>
        <source>CALL or DEF expected after TOOL</source>
        <translation>po TOOL oczekiwano CALL lub DEF</translation>
    </message>
    <message>
        <source>PGM expected</source>
        <translation>oczekiwano PGM</translation>
    </message>
    <message>
        <source>MM or INCH expected</source>
        <translation>oczekiwano MM lub INCH</translation>
    </message>
    <message>
        <source>FORM expected</source>
        <translation>oczekiwano FORM</translation>
    </message>
    <message>
        <source>axis expected</source>
        <translation>oczekiwano osi</translation>
    </message>
    <message>
        <source>0.1, 0.2 or CYLINDER expected</source>
        <translation>oczekiwano 0.1, 0.2 lub CYLINDER</translation>
    </message>
    <message>
        <source>tool axis expected</source>
        <translation>oczekiwano osi narzędzia</translation>
    </message>
    <message>
        <source>Q parameter expected</source>
        <translation>oczekiwano parametru Q</translation>
    </message>
    <message>
        <source>DECLARE STRING needs a QS parameter</source>
        <translation>DECLARE STRING wymaga parametru QS</translation>
    </message>
    <message>
        <source>FN number expected</source>
        <translation>oczekiwano numeru FN</translation>
    </message>
    <message>
        <source>&apos;:&apos; expected after FN {1}</source>
        <translation>po FN {1} oczekiwano &apos;:&apos;</translation>
    </message>
    <message>
        <source>square root of a negative number</source>
        <translation>pierwiastek kwadratowy z liczby ujemnej</translation>
    </message>
    <message>
        <source>&apos;IF&apos; expected</source>
        <translation>oczekiwano &apos;IF&apos;</translation>
    </message>
    <message>
        <source>&apos;GOTO&apos; expected</source>
        <translation>oczekiwano &apos;GOTO&apos;</translation>
    </message>
    <message>
        <source>&apos;LBL&apos; expected</source>
        <translation>oczekiwano &apos;LBL&apos;</translation>
    </message>
    <message>
        <source>&apos;ERROR&apos; expected</source>
        <translation>oczekiwano &apos;ERROR&apos;</translation>
    </message>
    <message>
        <source>&apos;PRINT&apos; expected</source>
        <translation>oczekiwano &apos;PRINT&apos;</translation>
    </message>
    <message>
        <source>&apos;F-PRINT&apos; expected</source>
        <translation>oczekiwano &apos;F-PRINT&apos;</translation>
    </message>
    <message>
        <source>&apos;mask file / output file&apos; expected</source>
        <translation>oczekiwano &apos;plik maski / plik wyjściowy&apos;</translation>
    </message>
    <message>
        <source>&apos;SYSREAD&apos; expected</source>
        <translation>oczekiwano &apos;SYSREAD&apos;</translation>
    </message>
    <message>
        <source>&apos;ID&apos; expected</source>
        <translation>oczekiwano &apos;ID&apos;</translation>
    </message>
    <message>
        <source>&apos;CDATA&apos; expected</source>
        <translation>oczekiwano &apos;CDATA&apos;</translation>
    </message>
    <message>
        <source>the parameter range runs past the last Q parameter</source>
        <translation>zakres parametrów wykracza poza ostatni parametr Q</translation>
    </message>
    <message>
        <source>&apos;TABOPEN&apos; expected</source>
        <translation>oczekiwano &apos;TABOPEN&apos;</translation>
    </message>
    <message>
        <source>table name expected</source>
        <translation>oczekiwano nazwy tabeli</translation>
    </message>
    <message>
        <source>&apos;/&apos; expected</source>
        <translation>oczekiwano &apos;/&apos;</translation>
    </message>
    <message>
        <source>column names in quotes expected</source>
        <translation>oczekiwano nazw kolumn w cudzysłowie</translation>
    </message>
    <message>
        <source>FN {1} does not exist</source>
        <translation>FN {1} nie istnieje</translation>
    </message>
    <message>
        <source>DEF or CALL expected after CYCL</source>
        <translation>po CYCL oczekiwano DEF lub CALL</translation>
    </message>
    <message>
        <source>file name expected</source>
        <translation>oczekiwano nazwy pliku</translation>
    </message>
    <message>
        <source>unknown block &apos;CYCLE&apos; (the keyword is CYCL)</source>
        <translation>nieznany blok &apos;CYCLE&apos; (słowo kluczowe to CYCL)</translation>
    </message>
    <message>
        <source>unknown block &apos;{1}&apos;</source>
        <translation>nieznany blok &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>label name must not be empty</source>
        <translation>nazwa etykiety nie może być pusta</translation>
    </message>
    <message>
        <source>label expected</source>
        <translation>oczekiwano etykiety</translation>
    </message>
    <message>
        <source>label number or name expected</source>
        <translation>oczekiwano numeru lub nazwy etykiety</translation>
    </message>
    <message>
        <source>label number must be between {1} and 65535</source>
        <translation>numer etykiety musi leżeć między {1} a 65535</translation>
    </message>
    <message>
        <source>cycle number expected</source>
        <translation>oczekiwano numeru cyklu</translation>
    </message>
    <message>
        <source>cycle parameter Qnnn= expected</source>
        <translation>oczekiwano parametru cyklu Qnnn=</translation>
    </message>
    <message>
        <source>cycle parameter number expected</source>
        <translation>oczekiwano numeru parametru cyklu</translation>
    </message>
    <message>
        <source>GLOBAL DEF group number expected</source>
        <translation>oczekiwano numeru grupy GLOBAL DEF</translation>
    </message>
    <message>
        <source>pattern element POS, ROW, PAT, FRAME, CIRC or PITCHCIRC expected</source>
        <translation>oczekiwano elementu wzorca POS, ROW, PAT, FRAME, CIRC lub PITCHCIRC</translation>
    </message>
    <message>
        <source>PATTERN DEF needs at least one pattern element</source>
        <translation>PATTERN DEF wymaga co najmniej jednego elementu wzorca</translation>
    </message>
    <message>
        <source>Spindle?</source>
        <translation>Wrzeciono?</translation>
    </message>
    <message>
        <source>Tool axis is missing</source>
        <translation>Brak osi narzędzia</translation>
    </message>
    <message>
        <source>Tool radius too small</source>
        <translation>Promień narzędzia za mały</translation>
    </message>
    <message>
        <source>Tool radius too large</source>
        <translation>Promień narzędzia za duży</translation>
    </message>
    <message>
        <source>Range exceeded</source>
        <translation>Zakres przekroczony</translation>
    </message>
    <message>
        <source>Start position incorrect</source>
        <translation>Nieprawidłowa pozycja startowa</translation>
    </message>
    <message>
        <source>ROTATION not permitted</source>
        <translation>OBRÓT niedozwolony</translation>
    </message>
    <message>
        <source>SCALING FACTOR not permitted</source>
        <translation>WSPÓŁCZYNNIK WYMIAROWY niedozwolony</translation>
    </message>
    <message>
        <source>MIRROR IMAGE not permitted</source>
        <translation>ODBICIE LUSTRZANE niedozwolone</translation>
    </message>
    <message>
        <source>Datum shift not permitted</source>
        <translation>Przesunięcie punktu zerowego niedozwolone</translation>
    </message>
    <message>
        <source>Feed rate is missing</source>
        <translation>Brak posuwu</translation>
    </message>
    <message>
        <source>Input value incorrect</source>
        <translation>Nieprawidłowa wartość wprowadzona</translation>
    </message>
    <message>
        <source>Incorrect sign</source>
        <translation>Nieprawidłowy znak liczby</translation>
    </message>
    <message>
        <source>Entered angle not permitted</source>
        <translation>Wprowadzony kąt niedozwolony</translation>
    </message>
    <message>
        <source>Touch point inaccessible</source>
        <translation>Punkt próbkowania nieosiągalny</translation>
    </message>
    <message>
        <source>Too many points</source>
        <translation>Zbyt wiele punktów</translation>
    </message>
    <message>
        <source>Contradictory input</source>
        <translation>Sprzeczne dane wejściowe</translation>
    </message>
    <message>
        <source>CYCL incomplete</source>
        <translation>CYCL niekompletny</translation>
    </message>
    <message>
        <source>Plane wrongly defined</source>
        <translation>Płaszczyzna błędnie zdefiniowana</translation>
    </message>
    <message>
        <source>Wrong axis programmed</source>
        <translation>Zaprogramowano niewłaściwą oś</translation>
    </message>
    <message>
        <source>Wrong RPM</source>
        <translation>Niewłaściwa prędkość obrotowa</translation>
    </message>
    <message>
        <source>Radius comp. undefined</source>
        <translation>Korekcja promienia nieokreślona</translation>
    </message>
    <message>
        <source>Rounding-off undefined</source>
        <translation>Zaokrąglenie nieokreślone</translation>
    </message>
    <message>
        <source>Rounding radius too large</source>
        <translation>Promień zaokrąglenia za duży</translation>
    </message>
    <message>
        <source>Program start undefined</source>
        <translation>Start programu nieokreślony</translation>
    </message>
    <message>
        <source>Excessive nesting</source>
        <translation>Zbyt głębokie zagnieżdżenie</translation>
    </message>
    <message>
        <source>Angle reference missing</source>
        <translation>Brak odniesienia kąta</translation>
    </message>
    <message>
        <source>No fixed cycle defined</source>
        <translation>Nie zdefiniowano cyklu obróbki</translation>
    </message>
    <message>
        <source>Slot width too small</source>
        <translation>Szerokość rowka za mała</translation>
    </message>
    <message>
        <source>Pocket too small</source>
        <translation>Kieszeń za mała</translation>
    </message>
    <message>
        <source>Q202 not defined</source>
        <translation>Q202 nie zdefiniowany</translation>
    </message>
    <message>
        <source>Q205 not defined</source>
        <translation>Q205 nie zdefiniowany</translation>
    </message>
    <message>
        <source>Q218 must be greater than Q219</source>
        <translation>Q218 musi być większy od Q219</translation>
    </message>
    <message>
        <source>CYCL 210 not permitted</source>
        <translation>CYCL 210 niedozwolony</translation>
    </message>
    <message>
        <source>CYCL 211 not permitted</source>
        <translation>CYCL 211 niedozwolony</translation>
    </message>
    <message>
        <source>Q220 too large</source>
        <translation>Q220 za duży</translation>
    </message>
    <message>
        <source>Q222 must be greater than Q223</source>
        <translation>Q222 musi być większy od Q223</translation>
    </message>
    <message>
        <source>Q244 must be greater than 0</source>
        <translation>Q244 musi być większy od 0</translation>
    </message>
    <message>
        <source>Q245 must not equal Q246</source>
        <translation>Q245 nie może być równy Q246</translation>
    </message>
    <message>
        <source>Angle range must be under 360 degrees</source>
        <translation>Zakres kąta musi być mniejszy niż 360 stopni</translation>
    </message>
    <message>
        <source>Q223 must be greater than Q222</source>
        <translation>Q223 musi być większy od Q222</translation>
    </message>
    <message>
        <source>Q214: 0 not permitted</source>
        <translation>Q214: 0 niedozwolone</translation>
    </message>
    <message>
        <source>Traverse direction not defined</source>
        <translation>Kierunek przemieszczenia nie zdefiniowany</translation>
    </message>
    <message>
        <source>No datum table active</source>
        <translation>Brak aktywnej tabeli punktów zerowych</translation>
    </message>
    <message>
        <source>Position error: center in axis 1</source>
        <translation>Błąd położenia: środek w osi 1</translation>
    </message>
    <message>
        <source>Position error: center in axis 2</source>
        <translation>Błąd położenia: środek w osi 2</translation>
    </message>
    <message>
        <source>Hole diameter too small</source>
        <translation>Średnica odwiertu za mała</translation>
    </message>
    <message>
        <source>Hole diameter too large</source>
        <translation>Średnica odwiertu za duża</translation>
    </message>
    <message>
        <source>Stud diameter too small</source>
        <translation>Średnica czopu za mała</translation>
    </message>
    <message>
        <source>Stud diameter too large</source>
        <translation>Średnica czopu za duża</translation>
    </message>
    <message>
        <source>Pocket too small: rework axis 1</source>
        <translation>Kieszeń za mała: do poprawki, oś 1</translation>
    </message>
    <message>
        <source>Pocket too small: rework axis 2</source>
        <translation>Kieszeń za mała: do poprawki, oś 2</translation>
    </message>
    <message>
        <source>Pocket too large: scrap axis 1</source>
        <translation>Kieszeń za duża: wyrób wadliwy, oś 1</translation>
    </message>
    <message>
        <source>Pocket too large: scrap axis 2</source>
        <translation>Kieszeń za duża: wyrób wadliwy, oś 2</translation>
    </message>
    <message>
        <source>Stud too small: scrap axis 1</source>
        <translation>Czop za mały: wyrób wadliwy, oś 1</translation>
    </message>
    <message>
        <source>Stud too small: scrap axis 2</source>
        <translation>Czop za mały: wyrób wadliwy, oś 2</translation>
    </message>
    <message>
        <source>Stud too large: rework axis 1</source>
        <translation>Czop za duży: do poprawki, oś 1</translation>
    </message>
    <message>
        <source>Stud too large: rework axis 2</source>
        <translation>Czop za duży: do poprawki, oś 2</translation>
    </message>
    <message>
        <source>TCHPROBE 425: length exceeds max</source>
        <translation>TCHPROBE 425: długość powyżej maksimum</translation>
    </message>
    <message>
        <source>TCHPROBE 425: length below min</source>
        <translation>TCHPROBE 425: długość poniżej minimum</translation>
    </message>
    <message>
        <source>TCHPROBE 426: length exceeds max</source>
        <translation>TCHPROBE 426: długość powyżej maksimum</translation>
    </message>
    <message>
        <source>TCHPROBE 426: length below min</source>
        <translation>TCHPROBE 426: długość poniżej minimum</translation>
    </message>
    <message>
        <source>TCHPROBE 430: diameter too large</source>
        <translation>TCHPROBE 430: średnica za duża</translation>
    </message>
    <message>
        <source>TCHPROBE 430: diameter too small</source>
        <translation>TCHPROBE 430: średnica za mała</translation>
    </message>
    <message>
        <source>No measuring axis defined</source>
        <translation>Nie zdefiniowano osi pomiarowej</translation>
    </message>
    <message>
        <source>Tool breakage tolerance exceeded</source>
        <translation>Przekroczona tolerancja pęknięcia narzędzia</translation>
    </message>
    <message>
        <source>Enter Q247 unequal 0</source>
        <translation>Wprowadzić Q247 różne od 0</translation>
    </message>
    <message>
        <source>Enter Q247 greater than 5</source>
        <translation>Wprowadzić Q247 większe od 5</translation>
    </message>
    <message>
        <source>Datum table?</source>
        <translation>Tabela punktów zerowych?</translation>
    </message>
    <message>
        <source>Enter Q351 unequal 0</source>
        <translation>Wprowadzić Q351 różne od 0</translation>
    </message>
    <message>
        <source>Thread depth too large</source>
        <translation>Głębokość gwintu za duża</translation>
    </message>
    <message>
        <source>Missing calibration data</source>
        <translation>Brak danych kalibrowania</translation>
    </message>
    <message>
        <source>Tolerance exceeded</source>
        <translation>Tolerancja przekroczona</translation>
    </message>
    <message>
        <source>Block scan active</source>
        <translation>Przebieg do bloku aktywny</translation>
    </message>
    <message>
        <source>ORIENTATION not permitted</source>
        <translation>ORIENTACJA niedozwolona</translation>
    </message>
    <message>
        <source>3DROT not permitted</source>
        <translation>3DROT niedozwolony</translation>
    </message>
    <message>
        <source>Activate 3DROT</source>
        <translation>Aktywować 3DROT</translation>
    </message>
    <message>
        <source>Enter depth as negative</source>
        <translation>Wprowadzić głębokość ze znakiem ujemnym</translation>
    </message>
    <message>
        <source>Q303 not defined in measuring cycle</source>
        <translation>Q303 nie zdefiniowany w cyklu pomiarowym</translation>
    </message>
    <message>
        <source>Tool axis not allowed</source>
        <translation>Oś narzędzia niedozwolona</translation>
    </message>
    <message>
        <source>Calculated values incorrect</source>
        <translation>Obliczone wartości nieprawidłowe</translation>
    </message>
    <message>
        <source>Contradictory measuring points</source>
        <translation>Sprzeczne punkty pomiarowe</translation>
    </message>
    <message>
        <source>Incorrect clearance height</source>
        <translation>Nieprawidłowa bezpieczna wysokość</translation>
    </message>
    <message>
        <source>Contradictory plunge type</source>
        <translation>Sprzeczny rodzaj wcięcia</translation>
    </message>
    <message>
        <source>This fixed cycle not allowed</source>
        <translation>Ten cykl obróbki niedozwolony</translation>
    </message>
    <message>
        <source>Line is write-protected</source>
        <translation>Wiersz chroniony przed zapisem</translation>
    </message>
    <message>
        <source>Oversize greater than depth</source>
        <translation>Naddatek większy od głębokości</translation>
    </message>
    <message>
        <source>No point angle defined</source>
        <translation>Nie zdefiniowano kąta wierzchołkowego</translation>
    </message>
    <message>
        <source>Contradictory data</source>
        <translation>Sprzeczne dane</translation>
    </message>
    <message>
        <source>Slot position 0 not allowed</source>
        <translation>Pozycja rowka 0 niedozwolona</translation>
    </message>
    <message>
        <source>Enter an infeed not equal to 0</source>
        <translation>Wprowadzić dosuw różny od 0</translation>
    </message>
    <message>
        <source>{1} is not defined for this value</source>
        <translation>{1} nie jest zdefiniowane dla tej wartości</translation>
    </message>
    <message>
        <source>a string parameter cannot be used as a number</source>
        <translation>parametru tekstowego nie można użyć jako liczby</translation>
    </message>
    <message>
        <source>{1}{2} does not exist (0 to {3})</source>
        <translation>{1}{2} nie istnieje (0 do {3})</translation>
    </message>
    <message>
        <source>number or Q parameter expected</source>
        <translation>oczekiwano liczby lub parametru Q</translation>
    </message>
    <message>
        <source>incomplete formula</source>
        <translation>niekompletna formuła</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in formula</source>
        <translation>nieoczekiwane &apos;{1}&apos; w formule</translation>
    </message>
    <message>
        <source>string parameter QS expected</source>
        <translation>oczekiwano parametru tekstowego QS</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a number</source>
        <translation>&apos;{1}&apos; nie jest liczbą</translation>
    </message>
    <message>
        <source>&apos;||&apos; expected</source>
        <translation>oczekiwano &apos;||&apos;</translation>
    </message>
    <message>
        <source>SUBSTR needs BEG and LEN of at least 0</source>
        <translation>SUBSTR wymaga BEG i LEN co najmniej 0</translation>
    </message>
    <message>
        <source>SYSSTR ID{1} NR{2} is not available</source>
        <translation>SYSSTR ID{1} NR{2} nie jest dostępny</translation>
    </message>
    <message>
        <source>string expected</source>
        <translation>oczekiwano tekstu</translation>
    </message>
    <message>
        <source>unknown keyword &apos;{1}&apos;</source>
        <translation>nieznane słowo kluczowe &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>the format has no closing quote</source>
        <translation>format nie ma zamykającego cudzysłowu</translation>
    </message>
    <message>
        <source>unknown value &apos;{1}&apos;</source>
        <translation>nieznana wartość &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>bad format field</source>
        <translation>błędne pole formatu</translation>
    </message>
    <message>
        <source>more fields than values</source>
        <translation>więcej pól niż wartości</translation>
    </message>
    <message>
        <source>a cycle cannot be called with radius compensation RL/RR: program R0</source>
        <translation>cyklu nie można wywołać z korekcją promienia RL/RR: zaprogramuj R0</translation>
    </message>
    <message>
        <source>the cycle calls of this block need more than {1} moves</source>
        <translation>wywołania cykli w tym bloku wymagają ponad {1} ruchów</translation>
    </message>
    <message>
        <source>no machining cycle is defined (CYCL DEF)</source>
        <translation>nie zdefiniowano cyklu obróbki (CYCL DEF)</translation>
    </message>
    <message>
        <source>CYCL CALL PAT: no PATTERN DEF or point table (SEL PATTERN) is active</source>
        <translation>CYCL CALL PAT: brak aktywnego PATTERN DEF lub tabeli punktów (SEL PATTERN)</translation>
    </message>
    <message>
        <source>CYCL CALL PAT cannot use FMAX (without F it moves at rapid)</source>
        <translation>CYCL CALL PAT nie może używać FMAX (bez F przemieszcza się na biegu szybkim)</translation>
    </message>
    <message>
        <source>CYCL CALL POS needs all three coordinates</source>
        <translation>CYCL CALL POS wymaga wszystkich trzech współrzędnych</translation>
    </message>
    <message>
        <source>cycle {1} needs a machining cycle defined before it</source>
        <translation>cykl {1} wymaga wcześniej zdefiniowanego cyklu obróbki</translation>
    </message>
    <message>
        <source>cycle {1} cannot call cycle {2}</source>
        <translation>cykl {1} nie może wywołać cyklu {2}</translation>
    </message>
    <message>
        <source>{1} has no parameter Q{2}: it is ignored</source>
        <translation>{1} nie ma parametru Q{2}: zostaje pominięty</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) is missing</source>
        <translation>{1}: brak parametru {2} ({3})</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) needs a text in quotes or a QS parameter</source>
        <translation>{1}: parametr {2} ({3}) wymaga tekstu w cudzysłowie lub parametru QS</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) does not accept {4}</source>
        <translation>{1}: parametr {2} ({3}) nie przyjmuje {4}</translation>
    </message>
    <message>
        <source>FAUTO: the TOOL CALL block gave no feed rate F</source>
        <translation>FAUTO: blok TOOL CALL nie podał posuwu F</translation>
    </message>
    <message>
        <source>{1}: {2} needs a feed value after {3}</source>
        <translation>{1}: {2} wymaga wartości posuwu po {3}</translation>
    </message>
    <message>
        <source>FZ needs the number of teeth (CUT) of the tool</source>
        <translation>FZ wymaga liczby ostrzy (CUT) narzędzia</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = &apos;{4}&apos; is not a value</source>
        <translation>{1}: parametr {2} ({3}) = &apos;{4}&apos; nie jest wartością</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = {4} must be a whole number from {5} to {6}</source>
        <translation>{1}: parametr {2} ({3}) = {4} musi być liczbą całkowitą od {5} do {6}</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = {4} is outside {5} to {6}</source>
        <translation>{1}: parametr {2} ({3}) = {4} leży poza zakresem {5} do {6}</translation>
    </message>
    <message>
        <source>cycle {1} is not supported yet</source>
        <translation>cykl {1} nie jest jeszcze obsługiwany</translation>
    </message>
    <message>
        <source>CYCL DEF {1}.{2} without CYCL DEF {1}.0 before it</source>
        <translation>CYCL DEF {1}.{2} bez poprzedzającego CYCL DEF {1}.0</translation>
    </message>
    <message>
        <source>GLOBAL DEF {1} does not exist</source>
        <translation>GLOBAL DEF {1} nie istnieje</translation>
    </message>
    <message>
        <source>cannot read the datum table {1}: {2}</source>
        <translation>nie można odczytać tabeli punktów zerowych {1}: {2}</translation>
    </message>
    <message>
        <source>cannot read the point table {1}: {2}</source>
        <translation>nie można odczytać tabeli punktów {1}: {2}</translation>
    </message>
    <message>
        <source>{1} is not supported yet</source>
        <translation>{1} nie jest jeszcze obsługiwane</translation>
    </message>
    <message>
        <source>FN 14 error {1}: {2}</source>
        <translation>FN 14 błąd {1}: {2}</translation>
    </message>
    <message>
        <source>FN 14 error {1}</source>
        <translation>FN 14 błąd {1}</translation>
    </message>
    <message>
        <source>cannot read the F-PRINT mask {1}</source>
        <translation>nie można odczytać maski F-PRINT {1}</translation>
    </message>
    <message>
        <source>F-PRINT mask {1} has an error</source>
        <translation>maska F-PRINT {1} zawiera błąd</translation>
    </message>
    <message>
        <source>cannot write {1}</source>
        <translation>nie można zapisać {1}</translation>
    </message>
    <message>
        <source>FN 18: SYSREAD ID{1} NR{2} IDX{3} is not available</source>
        <translation>FN 18: SYSREAD ID{1} NR{2} IDX{3} nie jest dostępny</translation>
    </message>
    <message>
        <source>FN {1}: the points do not define a circle</source>
        <translation>FN {1}: punkty nie określają okręgu</translation>
    </message>
    <message>
        <source>FN 26: cannot open table {1}</source>
        <translation>FN 26: nie można otworzyć tabeli {1}</translation>
    </message>
    <message>
        <source>no table is open (FN 26: TABOPEN)</source>
        <translation>żadna tabela nie jest otwarta (FN 26: TABOPEN)</translation>
    </message>
    <message>
        <source>FN 27: cannot write row {1}</source>
        <translation>FN 27: nie można zapisać wiersza {1}</translation>
    </message>
    <message>
        <source>FN 28: cannot read row {1}</source>
        <translation>FN 28: nie można odczytać wiersza {1}</translation>
    </message>
    <message>
        <source>cannot read the program: {1}</source>
        <translation>nie można odczytać programu: {1}</translation>
    </message>
    <message>
        <source>label {1} is not defined</source>
        <translation>etykieta {1} nie jest zdefiniowana</translation>
    </message>
    <message>
        <source>subprograms nested deeper than {1} levels</source>
        <translation>podprogramy zagnieżdżone głębiej niż {1} poziomów</translation>
    </message>
    <message>
        <source>program calls nested deeper than {1} levels</source>
        <translation>wywołania programów zagnieżdżone głębiej niż {1} poziomów</translation>
    </message>
    <message>
        <source>cannot call program {1}: {2}</source>
        <translation>nie można wywołać programu {1}: {2}</translation>
    </message>
    <message>
        <source>the called program {1} has errors</source>
        <translation>wywołany program {1} zawiera błędy</translation>
    </message>
    <message>
        <source>feed rate is missing</source>
        <translation>brak posuwu</translation>
    </message>
    <message>
        <source>M140 MB MAX: the tool axis has no limit</source>
        <translation>M140 MB MAX: oś narzędzia nie ma ograniczenia</translation>
    </message>
    <message>
        <source>tool {1} is not in the tool table</source>
        <translation>narzędzia {1} nie ma w tabeli narzędzi</translation>
    </message>
    <message>
        <source>no tool table: tool {1} and the following tools are used with length 0 and radius 0</source>
        <translation>brak tabeli narzędzi: narzędzie {1} i następne są używane z długością 0 i promieniem 0</translation>
    </message>
    <message>
        <source>tool {1} is locked (TL)</source>
        <translation>narzędzie {1} jest zablokowane (TL)</translation>
    </message>
    <message>
        <source>spindle speed {1} exceeds the machine&apos;s {2} rpm</source>
        <translation>prędkość obrotowa {1} przekracza {2} obr/min maszyny</translation>
    </message>
    <message>
        <source>BLK FORM 0.2 needs BLK FORM 0.1 before it</source>
        <translation>BLK FORM 0.2 wymaga wcześniej BLK FORM 0.1</translation>
    </message>
    <message>
        <source>the blank has no volume</source>
        <translation>półfabrykat nie ma objętości</translation>
    </message>
    <message>
        <source>CC axes {1} and {2} do not span a plane</source>
        <translation>osie CC {1} i {2} nie tworzą płaszczyzny</translation>
    </message>
    <message>
        <source>CC takes two coordinates of a plane</source>
        <translation>CC przyjmuje dwie współrzędne płaszczyzny</translation>
    </message>
    <message>
        <source>circular moves cannot use FMAX</source>
        <translation>ruchy kołowe nie mogą używać FMAX</translation>
    </message>
    <message>
        <source>direction of rotation DR+ or DR- missing</source>
        <translation>brak kierunku obrotu DR+ lub DR-</translation>
    </message>
    <message>
        <source>no circle of radius {1} passes through the start and end point</source>
        <translation>żaden okrąg o promieniu {1} nie przechodzi przez punkt startu i punkt końcowy</translation>
    </message>
    <message>
        <source>circle centre CC is not defined</source>
        <translation>środek okręgu CC nie jest zdefiniowany</translation>
    </message>
    <message>
        <source>the end point is not on the circle: radius {1} at the start, {2} at the end</source>
        <translation>punkt końcowy nie leży na okręgu: promień {1} na początku, {2} na końcu</translation>
    </message>
    <message>
        <source>a tangential arc needs a contour element before it</source>
        <translation>łuk styczny wymaga poprzedzającego elementu konturu</translation>
    </message>
    <message>
        <source>pole CC is not defined</source>
        <translation>biegun CC nie jest zdefiniowany</translation>
    </message>
    <message>
        <source>the end point lies on the tangent: no arc possible</source>
        <translation>punkt końcowy leży na stycznej: łuk niemożliwy</translation>
    </message>
    <message>
        <source>CP needs a polar angle PA or IPA</source>
        <translation>CP wymaga kąta biegunowego PA lub IPA</translation>
    </message>
    <message>
        <source>the sign of IPA does not match DR</source>
        <translation>znak IPA nie zgadza się z DR</translation>
    </message>
    <message>
        <source>{1} needs a positive length LEN</source>
        <translation>{1} wymaga dodatniej długości LEN</translation>
    </message>
    <message>
        <source>{1} CT needs an angle CCA (0 to 360) and a radius R</source>
        <translation>{1} CT wymaga kąta CCA (0 do 360) i promienia R</translation>
    </message>
    <message>
        <source>{1} LCT needs a radius R</source>
        <translation>{1} LCT wymaga promienia R</translation>
    </message>
    <message>
        <source>APPR needs radius compensation RL or RR</source>
        <translation>APPR wymaga korekcji promienia RL lub RR</translation>
    </message>
    <message>
        <source>DEP LCT needs the end point</source>
        <translation>DEP LCT wymaga punktu końcowego</translation>
    </message>
    <message>
        <source>an arc in the {1} plane cannot be rotated out of its plane or scaled with different factors</source>
        <translation>łuku w płaszczyźnie {1} nie można obrócić poza jego płaszczyznę ani skalować różnymi współczynnikami</translation>
    </message>
    <message>
        <source>cycle 7: no datum table selected (SEL TABLE)</source>
        <translation>cykl 7: nie wybrano tabeli punktów zerowych (SEL TABLE)</translation>
    </message>
    <message>
        <source>cycle 7: datum {1} is not in the datum table</source>
        <translation>cykl 7: punktu zerowego {1} nie ma w tabeli punktów zerowych</translation>
    </message>
    <message>
        <source>cycle 8: the tool axis {1} cannot be mirrored; it is left out</source>
        <translation>cykl 8: osi narzędzia {1} nie można odbić; zostaje pominięta</translation>
    </message>
    <message>
        <source>cycle 247: no preset table (PRESET.PR) to read preset {1} from</source>
        <translation>cykl 247: brak tabeli punktów odniesienia (PRESET.PR), z której można odczytać punkt odniesienia {1}</translation>
    </message>
    <message>
        <source>cycle 247: preset {1} is not in the preset table</source>
        <translation>cykl 247: punktu odniesienia {1} nie ma w tabeli punktów odniesienia</translation>
    </message>
    <message>
        <source>cycle {1}: {2} expected</source>
        <translation>cykl {1}: oczekiwano {2}</translation>
    </message>
    <message>
        <source>cycle 12: program name expected</source>
        <translation>cykl 12: oczekiwano nazwy programu</translation>
    </message>
    <message>
        <source>cycle 18 has no sub-block 18.{1}</source>
        <translation>cykl 18 nie ma podbloku 18.{1}</translation>
    </message>
    <message>
        <source>cycle 32: unexpected &apos;{1}&apos;</source>
        <translation>cykl 32: nieoczekiwane &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>block number {1} is out of order (after {2})</source>
        <translation>numer bloku {1} poza kolejnością (po {2})</translation>
    </message>
    <message>
        <source>BEGIN PGM must be the first block</source>
        <translation>BEGIN PGM musi być pierwszym blokiem</translation>
    </message>
    <message>
        <source>END PGM {1} does not match BEGIN PGM {2}</source>
        <translation>END PGM {1} nie pasuje do BEGIN PGM {2}</translation>
    </message>
    <message>
        <source>label {1} is defined twice</source>
        <translation>etykieta {1} jest zdefiniowana dwukrotnie</translation>
    </message>
    <message>
        <source>{1} is not supported yet; the program cannot run past this block</source>
        <translation>{1} nie jest jeszcze obsługiwane; program nie może wykonać się poza ten blok</translation>
    </message>
    <message>
        <source>cycle {1} is not supported yet; the program cannot run past this block</source>
        <translation>cykl {1} nie jest jeszcze obsługiwany; program nie może wykonać się poza ten blok</translation>
    </message>
    <message>
        <source>block has no number while others have</source>
        <translation>blok nie ma numeru, choć inne mają</translation>
    </message>
    <message>
        <source>the program has no BEGIN PGM block</source>
        <translation>program nie ma bloku BEGIN PGM</translation>
    </message>
    <message>
        <source>the program has no END PGM block</source>
        <translation>program nie ma bloku END PGM</translation>
    </message>
    <message>
        <source>expected QRn=value</source>
        <translation>oczekiwano QRn=wartość</translation>
    </message>
    <message>
        <source>a rounding or chamfer must be followed by a contour element in the working plane</source>
        <translation>po zaokrągleniu lub fazie musi następować element konturu w płaszczyźnie obróbki</translation>
    </message>
    <message>
        <source>a chamfer needs straight lines on both sides</source>
        <translation>faza wymaga prostych po obu stronach</translation>
    </message>
    <message>
        <source>the chamfer is longer than the adjacent element</source>
        <translation>faza jest dłuższa od przyległego elementu</translation>
    </message>
    <message>
        <source>the rounding radius does not fit between the elements</source>
        <translation>promień zaokrąglenia nie mieści się między elementami</translation>
    </message>
    <message>
        <source>a rounding needs a contour element before it</source>
        <translation>zaokrąglenie wymaga poprzedzającego elementu konturu</translation>
    </message>
    <message>
        <source>a chamfer needs a contour element before it</source>
        <translation>faza wymaga poprzedzającego elementu konturu</translation>
    </message>
    <message>
        <source>a rounding or chamfer must be followed by a contour element</source>
        <translation>po zaokrągleniu lub fazie musi następować element konturu</translation>
    </message>
    <message>
        <source>an approach must be followed by a compensated contour element</source>
        <translation>po dosunięciu musi następować skorygowany element konturu</translation>
    </message>
    <message>
        <source>an approach needs RL or RR</source>
        <translation>dosunięcie wymaga RL lub RR</translation>
    </message>
    <message>
        <source>a departure needs a compensated contour element before it</source>
        <translation>odsunięcie wymaga poprzedzającego skorygowanego elementu konturu</translation>
    </message>
    <message>
        <source>the departure cannot be constructed with these values</source>
        <translation>odsunięcia nie można skonstruować z tymi wartościami</translation>
    </message>
    <message>
        <source>leave radius compensation with a straight line</source>
        <translation>korekcję promienia należy zakończyć prostą</translation>
    </message>
    <message>
        <source>switching between RL and RR needs a block with R0 between</source>
        <translation>przełączenie między RL i RR wymaga bloku z R0 pomiędzy</translation>
    </message>
    <message>
        <source>radius compensation must begin with a straight line</source>
        <translation>korekcja promienia musi zaczynać się prostą</translation>
    </message>
    <message>
        <source>the approach cannot be constructed with these values</source>
        <translation>dosunięcia nie można skonstruować z tymi wartościami</translation>
    </message>
    <message>
        <source>base = {1} is not a built-in machine ({2})</source>
        <translation>base = {1} nie jest wbudowaną maszyną ({2})</translation>
    </message>
    <message>
        <source>{1} must be a table</source>
        <translation>{1} musi być tabelą</translation>
    </message>
    <message>
        <source>axes must be a table of axes such as [axes.X]</source>
        <translation>axes musi być tabelą osi, np. [axes.X]</translation>
    </message>
    <message>
        <source>{1}: {2} is not an axis letter; use one of {3}</source>
        <translation>{1}: {2} nie jest literą osi; użyj jednej z {3}</translation>
    </message>
    <message>
        <source>{1} is a table; expected {2}</source>
        <translation>{1} jest tabelą; oczekiwano {2}</translation>
    </message>
    <message>
        <source>{1} = {2} is {3}; expected {4}</source>
        <translation>{1} = {2} to {3}; oczekiwano {4}</translation>
    </message>
    <message>
        <source>unknown key {1}</source>
        <translation>nieznany klucz {1}</translation>
    </message>
    <message>
        <source>unknown key {1}; did you mean {2}?</source>
        <translation>nieznany klucz {1}; czy chodziło o {2}?</translation>
    </message>
    <message>
        <source>TOML syntax error: {1}</source>
        <translation>błąd składni TOML: {1}</translation>
    </message>
    <message>
        <source>cannot read the machine configuration: {1}</source>
        <translation>nie można odczytać konfiguracji maszyny: {1}</translation>
    </message>
    <message>
        <source>Name shown to the operator</source>
        <translation>Nazwa wyświetlana operatorowi</translation>
    </message>
    <message>
        <source>Machine kind; selects the program dialects and lathe conventions</source>
        <translation>Rodzaj maszyny; wybiera dialekty programów i konwencje tokarskie</translation>
    </message>
    <message>
        <source>Axis the tool points along; tool length compensation acts on it</source>
        <translation>Oś, wzdłuż której skierowane jest narzędzie; działa na nią korekcja długości narzędzia</translation>
    </message>
    <message>
        <source>Path velocity of rapid moves</source>
        <translation>Prędkość torowa ruchów szybkich</translation>
    </message>
    <message>
        <source>Highest programmable feed rate</source>
        <translation>Najwyższy programowalny posuw</translation>
    </message>
    <message>
        <source>Period of the servo cycle</source>
        <translation>Okres cyklu serwo</translation>
    </message>
    <message>
        <source>Default path deviation allowed when blending corners; 0 stops exactly</source>
        <translation>Domyślne dopuszczalne odchylenie toru przy wygładzaniu narożników; 0 zatrzymuje dokładnie</translation>
    </message>
    <message>
        <source>Lowest spindle speed</source>
        <translation>Najniższa prędkość obrotowa wrzeciona</translation>
    </message>
    <message>
        <source>Highest spindle speed</source>
        <translation>Najwyższa prędkość obrotowa wrzeciona</translation>
    </message>
    <message>
        <source>CANopen node-ID of the spindle drive; 0: the spindle has none</source>
        <translation>Node-ID CANopen napędu wrzeciona; 0: wrzeciono go nie ma</translation>
    </message>
    <message>
        <source>Spindle drive position units per degree</source>
        <translation>Jednostki położenia napędu wrzeciona na stopień</translation>
    </message>
    <message>
        <source>CiA 402 mode of the spindle drive: cyclic synchronous or profile velocity</source>
        <translation>Tryb CiA 402 napędu wrzeciona: cykliczny synchroniczny lub prędkość profilowa</translation>
    </message>
    <message>
        <source>Lathe: diameter of the bar simulated when the program defines no blank; 0: none</source>
        <translation>Tokarka: średnica symulowanego pręta, gdy program nie definiuje półfabrykatu; 0: brak</translation>
    </message>
    <message>
        <source>Lathe: length of the simulated bar</source>
        <translation>Tokarka: długość symulowanego pręta</translation>
    </message>
    <message>
        <source>Lathe: workpiece Z of the bar&apos;s face; the bar reaches down to face_z - length</source>
        <translation>Tokarka: Z obrabianego przedmiotu na czole pręta; pręt sięga w dół do face_z - length</translation>
    </message>
    <message>
        <source>Lathe: inner diameter of a tube; 0: a solid bar</source>
        <translation>Tokarka: średnica wewnętrzna rury; 0: pręt pełny</translation>
    </message>
    <message>
        <source>SocketCAN interface of the drive bus</source>
        <translation>Interfejs SocketCAN magistrali napędów</translation>
    </message>
    <message>
        <source>Bit rate of the drive bus (a CiA 301 rate)</source>
        <translation>Szybkość transmisji magistrali napędów (szybkość wg CiA 301)</translation>
    </message>
    <message>
        <source>SYNC period of the drive bus; a whole multiple of servo_period</source>
        <translation>Okres SYNC magistrali napędów; całkowita wielokrotność servo_period</translation>
    </message>
    <message>
        <source>Heartbeat period of every drive (0x1017)</source>
        <translation>Okres heartbeat każdego napędu (0x1017)</translation>
    </message>
    <message>
        <source>A drive whose heartbeat is missing this long is lost; above heartbeat_period</source>
        <translation>Napęd, którego heartbeat nie ma przez ten czas, jest utracony; powyżej heartbeat_period</translation>
    </message>
    <message>
        <source>A drive whose feedback PDO is missing this many cycles is lost</source>
        <translation>Napęd, którego PDO sprzężenia zwrotnego brakuje przez tyle cykli, jest utracony</translation>
    </message>
    <message>
        <source>CANopen node-ID of the control&apos;s heartbeat, watched by the drives</source>
        <translation>Node-ID CANopen heartbeatu sterowania, nadzorowanego przez napędy</translation>
    </message>
    <message>
        <source>Vendor-ID every drive must report (0x1018 sub 1), hexadecimal like 0x0000029C; empty: not checked</source>
        <translation>Vendor-ID, który musi zgłosić każdy napęd (0x1018 sub 1), szesnastkowo, np. 0x0000029C; puste: nie sprawdzane</translation>
    </message>
    <message>
        <source>Product code every drive must report (0x1018 sub 2); empty: not checked</source>
        <translation>Kod produktu, który musi zgłosić każdy napęd (0x1018 sub 2); puste: nie sprawdzane</translation>
    </message>
    <message>
        <source>Linear or rotary; A, B and C default to rotary</source>
        <translation>Liniowa lub obrotowa; A, B i C są domyślnie obrotowe</translation>
    </message>
    <message>
        <source>Lower soft limit in machine coordinates (a radius on a lathe)</source>
        <translation>Dolny wyłącznik programowy we współrzędnych maszyny (promień na tokarce)</translation>
    </message>
    <message>
        <source>Upper soft limit in machine coordinates (a radius on a lathe)</source>
        <translation>Górny wyłącznik programowy we współrzędnych maszyny (promień na tokarce)</translation>
    </message>
    <message>
        <source>Highest velocity of the axis</source>
        <translation>Najwyższa prędkość osi</translation>
    </message>
    <message>
        <source>Highest acceleration of the axis</source>
        <translation>Najwyższe przyspieszenie osi</translation>
    </message>
    <message>
        <source>Highest jerk of the axis</source>
        <translation>Najwyższy jerk (udar) osi</translation>
    </message>
    <message>
        <source>Machine position after homing; must lie within the soft limits</source>
        <translation>Położenie maszyny po bazowaniu; musi leżeć w obrębie wyłączników programowych</translation>
    </message>
    <message>
        <source>The axis may be absent and is then switched off with enabled = false</source>
        <translation>Oś może nie występować i jest wtedy wyłączana przez enabled = false</translation>
    </message>
    <message>
        <source>The axis is present; only optional axes may be disabled</source>
        <translation>Oś jest obecna; wyłączać można tylko osie opcjonalne</translation>
    </message>
    <message>
        <source>Lathe: the axis is programmed and displayed as a diameter</source>
        <translation>Tokarka: oś jest programowana i wyświetlana jako średnica</translation>
    </message>
    <message>
        <source>CANopen node-ID of the axis drive; 0: none</source>
        <translation>Node-ID CANopen napędu osi; 0: brak</translation>
    </message>
    <message>
        <source>Drive position units per millimetre or degree</source>
        <translation>Jednostki położenia napędu na milimetr lub stopień</translation>
    </message>
    <message>
        <source>Following error the drive allows (0x6065) before it faults</source>
        <translation>Uchyb nadążania dopuszczany przez napęd (0x6065), zanim zgłosi błąd</translation>
    </message>
    <message>
        <source>the machine has no axis for {1}</source>
        <translation>maszyna nie ma osi dla {1}</translation>
    </message>
    <message>
        <source>{1} = {2} must be less than {3} = {4}</source>
        <translation>{1} = {2} musi być mniejsze niż {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the soft limits {3} … {4} {5}</source>
        <translation>{1} = {2} leży poza wyłącznikami programowymi {3} … {4} {5}</translation>
    </message>
    <message>
        <source>{1} = false is only allowed when {2} = true</source>
        <translation>{1} = false jest dozwolone tylko, gdy {2} = true</translation>
    </message>
    <message>
        <source>{1} = true is only allowed on a linear axis of a lathe</source>
        <translation>{1} = true jest dozwolone tylko na osi liniowej tokarki</translation>
    </message>
    <message>
        <source>the machine has no axes; add [axes.X] tables or start from a built-in machine with base = &quot;mill&quot;</source>
        <translation>maszyna nie ma osi; dodaj tabele [axes.X] lub zacznij od wbudowanej maszyny z base = &quot;mill&quot;</translation>
    </message>
    <message>
        <source>axis letter {1} is not one of {2}</source>
        <translation>litera osi {1} nie należy do {2}</translation>
    </message>
    <message>
        <source>axis {1} is listed twice</source>
        <translation>oś {1} występuje na liście dwukrotnie</translation>
    </message>
    <message>
        <source>tool_axis = {1} is not an enabled axis of this machine ({2})</source>
        <translation>tool_axis = {1} nie jest włączoną osią tej maszyny ({2})</translation>
    </message>
    <message>
        <source>tool_axis = {1} must be a linear axis</source>
        <translation>tool_axis = {1} musi być osią liniową</translation>
    </message>
    <message>
        <source>{1} = {2} must not exceed {3} = {4}</source>
        <translation>{1} = {2} nie może przekraczać {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} must be smaller than {3} = {4}</source>
        <translation>{1} = {2} musi być mniejsze od {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} is the node-ID of drives.master_node</source>
        <translation>{1} = {2} to node-ID drives.master_node</translation>
    </message>
    <message>
        <source>{1} = {2} is already the node of {3}</source>
        <translation>{1} = {2} jest już węzłem {3}</translation>
    </message>
    <message>
        <source>drives.cycle_period = {1} must be a whole multiple of servo_period = {2}</source>
        <translation>drives.cycle_period = {1} musi być całkowitą wielokrotnością servo_period = {2}</translation>
    </message>
    <message>
        <source>drives.heartbeat_timeout = {1} must exceed drives.heartbeat_period = {2}</source>
        <translation>drives.heartbeat_timeout = {1} musi przekraczać drives.heartbeat_period = {2}</translation>
    </message>
    <message>
        <source>drives.bitrate = {1} is not a CiA 301 bit rate (10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)</source>
        <translation>drives.bitrate = {1} nie jest szybkością CiA 301 (10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)</translation>
    </message>
    <message>
        <source>{1} = &quot;{2}&quot; is not a 32-bit number such as 0x0000029C</source>
        <translation>{1} = &quot;{2}&quot; nie jest liczbą 32-bitową, np. 0x0000029C</translation>
    </message>
    <message>
        <source>{1} = {2} has the wrong type; expected {3}</source>
        <translation>{1} = {2} ma niewłaściwy typ; oczekiwano {3}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the allowed range {3}</source>
        <translation>{1} = {2} leży poza dozwolonym zakresem {3}</translation>
    </message>
    <message>
        <source>{1} = {2} is not one of {3}</source>
        <translation>{1} = {2} nie jest żadną z wartości {3}</translation>
    </message>
    <message>
        <source>empty file name</source>
        <translation>pusta nazwa pliku</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is outside the NC root</source>
        <translation>&apos;{1}&apos; leży poza katalogiem głównym NC</translation>
    </message>
    <message>
        <source>datum {1} is not in the datum table</source>
        <translation>punktu zerowego {1} nie ma w tabeli punktów zerowych</translation>
    </message>
    <message>
        <source>datum {1} is already in the datum table</source>
        <translation>punkt zerowy {1} jest już w tabeli punktów zerowych</translation>
    </message>
    <message>
        <source>the table does not start with a BEGIN line</source>
        <translation>tabela nie zaczyna się od wiersza BEGIN</translation>
    </message>
    <message>
        <source>the BEGIN line names no table</source>
        <translation>wiersz BEGIN nie podaje tabeli</translation>
    </message>
    <message>
        <source>the BEGIN line gives no file type</source>
        <translation>wiersz BEGIN nie podaje typu pliku</translation>
    </message>
    <message>
        <source>the table has no column {1}</source>
        <translation>tabela nie ma kolumny {1}</translation>
    </message>
    <message>
        <source>column {1} needs a whole number &gt;= 0, not &quot;{2}&quot;</source>
        <translation>kolumna {1} wymaga liczby całkowitej &gt;= 0, nie &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>the table has no row {1}</source>
        <translation>tabela nie ma wiersza {1}</translation>
    </message>
    <message>
        <source>the table has no column &quot;{1}&quot;</source>
        <translation>tabela nie ma kolumny &quot;{1}&quot;</translation>
    </message>
    <message>
        <source>cell {1} of row {2} is empty</source>
        <translation>komórka {1} wiersza {2} jest pusta</translation>
    </message>
    <message>
        <source>column {1} needs a number, not &quot;{2}&quot;</source>
        <translation>kolumna {1} wymaga liczby, nie &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>{1} columns named but {2} values given</source>
        <translation>podano {1} nazw kolumn, ale {2} wartości</translation>
    </message>
    <message>
        <source>column {1} holds text, not numbers</source>
        <translation>kolumna {1} zawiera tekst, nie liczby</translation>
    </message>
    <message>
        <source>point {1} is not in the point table</source>
        <translation>punktu {1} nie ma w tabeli punktów</translation>
    </message>
    <message>
        <source>column {1} needs Y or nothing, not &quot;{2}&quot;</source>
        <translation>kolumna {1} wymaga Y lub niczego, nie &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>point {1} is already in the point table</source>
        <translation>punkt {1} jest już w tabeli punktów</translation>
    </message>
    <message>
        <source>preset {1} is not in the preset table</source>
        <translation>punktu odniesienia {1} nie ma w tabeli punktów odniesienia</translation>
    </message>
    <message>
        <source>preset {1} is already in the preset table</source>
        <translation>punkt odniesienia {1} jest już w tabeli punktów odniesienia</translation>
    </message>
    <message>
        <source>column {1} needs a whole number, not &quot;{2}&quot;</source>
        <translation>kolumna {1} wymaga liczby całkowitej, nie &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>the key column {1} is empty</source>
        <translation>kolumna klucza {1} jest pusta</translation>
    </message>
    <message>
        <source>{1} {2} appears twice (first in line {3})</source>
        <translation>{1} {2} występuje dwukrotnie (pierwszy raz w wierszu {3})</translation>
    </message>
    <message>
        <source>the table has no column header line</source>
        <translation>tabela nie ma wiersza nagłówka kolumn</translation>
    </message>
    <message>
        <source>the table has no cell at row {1}, column {2}</source>
        <translation>tabela nie ma komórki w wierszu {1}, kolumnie {2}</translation>
    </message>
    <message>
        <source>a cell of column {1} cannot hold a line break</source>
        <translation>komórka kolumny {1} nie może zawierać podziału wiersza</translation>
    </message>
    <message>
        <source>{2} does not fit into column {1} ({3} characters)</source>
        <translation>{2} nie mieści się w kolumnie {1} ({3} znaków)</translation>
    </message>
    <message>
        <source>column {1} cannot hold an infinite number</source>
        <translation>kolumna {1} nie może zawierać liczby nieskończonej</translation>
    </message>
    <message>
        <source>cannot insert a row at {1}: the table has {2} rows</source>
        <translation>nie można wstawić wiersza w {1}: tabela ma {2} wierszy</translation>
    </message>
    <message>
        <source>&quot;{2}&quot; cannot be a key of column {1}</source>
        <translation>&quot;{2}&quot; nie może być kluczem kolumny {1}</translation>
    </message>
    <message>
        <source>column {1} needs L, 1, 0 or nothing, not &quot;{2}&quot;</source>
        <translation>kolumna {1} wymaga L, 1, 0 lub niczego, nie &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>tool {1} is already in the tool table</source>
        <translation>narzędzie {1} jest już w tabeli narzędzi</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>bezczynny</translation>
    </message>
    <message>
        <source>running</source>
        <translation>w toku</translation>
    </message>
    <message>
        <source>feed hold</source>
        <translation>zatrzymanie posuwu</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>zatrzymany</translation>
    </message>
    <message>
        <source>waiting for the machine</source>
        <translation>oczekiwanie na maszynę</translation>
    </message>
    <message>
        <source>finished</source>
        <translation>zakończony</translation>
    </message>
    <message>
        <source>error</source>
        <translation>błąd</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>przerwany</translation>
    </message>
    <message>
        <source>motion refused the block: {1}</source>
        <translation>ruch odrzucił blok: {1}</translation>
    </message>
    <message>
        <source>motion stopped: {1}</source>
        <translation>ruch zatrzymany: {1}</translation>
    </message>
    <message>
        <source>column {1} must be greater than 0, not {2}</source>
        <translation>kolumna {1} musi być większa od 0, nie {2}</translation>
    </message>
    <message>
        <source>column {1} must not be negative, not {2}</source>
        <translation>kolumna {1} nie może być ujemna, nie {2}</translation>
    </message>
    <message>
        <source>column {1} needs {2} or {3}, not &quot;{4}&quot;</source>
        <translation>kolumna {1} wymaga {2} lub {3}, nie &quot;{4}&quot;</translation>
    </message>
    <message>
        <source>{1} needs the coordinates of its end point</source>
        <translation>{1} wymaga współrzędnych swojego punktu końcowego</translation>
    </message>
    <message>
        <source>{1} is a straight probing move in workpiece coordinates: not with G06, G08, G09, G36-G39 or G53</source>
        <translation>{1} to prostoliniowy ruch próbkowania we współrzędnych obrabianego przedmiotu: nie z G06, G08, G09, G36-G39 ani G53</translation>
    </message>
    <message>
        <source>G75 reached its end point without the probe touching</source>
        <translation>G75 osiągnęło punkt końcowy bez zetknięcia sondy</translation>
    </message>
    <message>
        <source>G76 reached its end point with the probe still touching</source>
        <translation>G76 osiągnęło punkt końcowy, a sonda nadal dotyka</translation>
    </message>
    <message>
        <source>Simulation: a box-shaped workpiece the touch probe touches (G75, probing cycles); the bounds below, machine coordinates of the tool tip</source>
        <translation>Symulacja: prostopadłościenny obrabiany przedmiot, którego dotyka sonda (G75, cykle próbkowania); granice poniżej we współrzędnych maszyny wierzchołka narzędzia</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine X of the tool tip inside it</source>
        <translation>Symulowany przedmiot do próbkowania: najmniejsze X maszyny wierzchołka narzędzia wewnątrz niego</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine X of the tool tip inside it</source>
        <translation>Symulowany przedmiot do próbkowania: największe X maszyny wierzchołka narzędzia wewnątrz niego</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine Y of the tool tip inside it</source>
        <translation>Symulowany przedmiot do próbkowania: najmniejsze Y maszyny wierzchołka narzędzia wewnątrz niego</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine Y of the tool tip inside it</source>
        <translation>Symulowany przedmiot do próbkowania: największe Y maszyny wierzchołka narzędzia wewnątrz niego</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine Z of the tool tip inside it</source>
        <translation>Symulowany przedmiot do próbkowania: najmniejsze Z maszyny wierzchołka narzędzia wewnątrz niego</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine Z of the tool tip inside it</source>
        <translation>Symulowany przedmiot do próbkowania: największe Z maszyny wierzchołka narzędzia wewnątrz niego</translation>
    </message>
    <message>
        <source>Machine coordinate of the workpiece origin (the default preset); kerf run --work-offset overrides it</source>
        <translation>Współrzędna maszyny punktu zerowego obrabianego przedmiotu (domyślny punkt odniesienia); kerf run --work-offset ją zastępuje</translation>
    </message>
    <message>
        <source>{1} needs a programmed feed F greater than 0</source>
        <translation>{1} wymaga zaprogramowanego posuwu F większego od 0</translation>
    </message>
    <message>
        <source>Drilling/
thread</source>
        <translation>Wiercenie/
gwint</translation>
    </message>
    <message>
        <source>Pockets/
studs/slots</source>
        <translation>Kieszenie/
czopy/rowki</translation>
    </message>
    <message>
        <source>Patterns</source>
        <translation>Wzory</translation>
    </message>
    <message>
        <source>SL cycles</source>
        <translation>Cykle SL</translation>
    </message>
    <message>
        <source>Coordinate
transform.</source>
        <translation>Przeliczanie
współrzędnych</translation>
    </message>
    <message>
        <source>Special
cycles</source>
        <translation>Cykle
specjalne</translation>
    </message>
    <message>
        <source>SET-UP CLEARANCE</source>
        <translation>ODSTĘP BEZPIECZEŃSTWA</translation>
    </message>
    <message>
        <source>DEPTH</source>
        <translation>GŁĘBOKOŚĆ</translation>
    </message>
    <message>
        <source>PLUNGING DEPTH</source>
        <translation>GŁĘBOKOŚĆ DOSUWU</translation>
    </message>
    <message>
        <source>SURFACE COORDINATE</source>
        <translation>WSPÓŁ. POWIERZCHNI</translation>
    </message>
    <message>
        <source>2ND SET-UP CLEARANCE</source>
        <translation>2. ODSTĘP BEZPIECZ.</translation>
    </message>
    <message>
        <source>MIN. PLUNGING DEPTH</source>
        <translation>MIN. GŁĘB. DOSUWU</translation>
    </message>
    <message>
        <source>FEED RATE FOR PLNGNG</source>
        <translation>POSUW WCIĘCIA</translation>
    </message>
    <message>
        <source>FEED RATE FOR MILLING</source>
        <translation>POSUW FREZOWANIA</translation>
    </message>
    <message>
        <source>RETRACTION FEED RATE</source>
        <translation>POSUW POWROTU</translation>
    </message>
    <message>
        <source>DWELL TIME AT TOP</source>
        <translation>CZAS PRZERWY U GÓRY</translation>
    </message>
    <message>
        <source>DWELL TIME AT DEPTH</source>
        <translation>CZAS PRZERWY NA DOLE</translation>
    </message>
    <message>
        <source>DECREMENT</source>
        <translation>WARTOŚĆ ZMNIEJSZENIA</translation>
    </message>
    <message>
        <source>NR OF BREAKS</source>
        <translation>ŁAMANIA WIÓRA</translation>
    </message>
    <message>
        <source>DISENGAGING DIRECTN</source>
        <translation>KIERUNEK ODSUNIĘCIA</translation>
    </message>
    <message>
        <source>CENTER IN 1ST AXIS</source>
        <translation>ŚRODEK 1. OSI</translation>
    </message>
    <message>
        <source>CENTER IN 2ND AXIS</source>
        <translation>ŚRODEK 2. OSI</translation>
    </message>
    <message>
        <source>FIRST SIDE LENGTH</source>
        <translation>DŁUGOŚĆ 1. BOKU</translation>
    </message>
    <message>
        <source>2ND SIDE LENGTH</source>
        <translation>DŁUGOŚĆ 2. BOKU</translation>
    </message>
    <message>
        <source>ANGLE OF ROTATION</source>
        <translation>KĄT OBROTU</translation>
    </message>
    <message>
        <source>STARTNG PNT 1ST AXIS</source>
        <translation>PUNKT STARTU 1. OSI</translation>
    </message>
    <message>
        <source>STARTNG PNT 2ND AXIS</source>
        <translation>PUNKT STARTU 2. OSI</translation>
    </message>
    <message>
        <source>STARTNG PNT 3RD AXIS</source>
        <translation>PUNKT STARTU 3. OSI</translation>
    </message>
    <message>
        <source>SPACING IN 1ST AXIS</source>
        <translation>ODSTĘP 1. OSI</translation>
    </message>
    <message>
        <source>SPACING IN 2ND AXIS</source>
        <translation>ODSTĘP 2. OSI</translation>
    </message>
    <message>
        <source>THREAD PITCH</source>
        <translation>SKOK GWINTU</translation>
    </message>
    <message>
        <source>NR OF REPETITIONS</source>
        <translation>LICZBA POWTÓRZEŃ</translation>
    </message>
    <message>
        <source>NUMBER OF COLUMNS</source>
        <translation>LICZBA KOLUMN</translation>
    </message>
    <message>
        <source>NUMBER OF LINES</source>
        <translation>LICZBA WIERSZY</translation>
    </message>
    <message>
        <source>PITCH CIRCLE DIAMETR</source>
        <translation>ŚREDNICA KOŁA PODZ.</translation>
    </message>
    <message>
        <source>STARTING ANGLE</source>
        <translation>KĄT STARTU</translation>
    </message>
    <message>
        <source>STOPPING ANGLE</source>
        <translation>KĄT KOŃCOWY</translation>
    </message>
    <message>
        <source>STEPPING ANGLE</source>
        <translation>KROK KĄTA</translation>
    </message>
    <message>
        <source>DEPTH OF COUNTERBORE</source>
        <translation>GŁĘB. POGŁĘBIENIA</translation>
    </message>
    <message>
        <source>MATERIAL THICKNESS</source>
        <translation>GRUBOŚĆ MATERIAŁU</translation>
    </message>
    <message>
        <source>OFF-CENTER DISTANCE</source>
        <translation>WYMIAR MIMOŚRODU</translation>
    </message>
    <message>
        <source>TOOL EDGE HEIGHT</source>
        <translation>WYSOKOŚĆ OSTRZA</translation>
    </message>
    <message>
        <source>F PRE-POSITIONING</source>
        <translation>POSUW POZYC. WSTĘP.</translation>
    </message>
    <message>
        <source>F COUNTERSINKING</source>
        <translation>POSUW POGŁĘBIANIA</translation>
    </message>
    <message>
        <source>DIST FOR CHIP BRKNG</source>
        <translation>ODC. POWR. ŁAM. WIÓRA</translation>
    </message>
    <message>
        <source>DEPTH FOR CHIP BRKNG</source>
        <translation>GŁĘB. ŁAMANIA WIÓRA</translation>
    </message>
    <message>
        <source>UPPER ADV STOP DIST</source>
        <translation>GÓRNY ODST. WYPRZEDZ.</translation>
    </message>
    <message>
        <source>LOWER ADV STOP DIST</source>
        <translation>DOLNY ODST. WYPRZEDZ.</translation>
    </message>
    <message>
        <source>MOVE TO CLEARANCE</source>
        <translation>NA BEZPIECZNĄ WYS.</translation>
    </message>
    <message>
        <source>NOMINAL DIAMETER</source>
        <translation>ŚREDNICA NOMINALNA</translation>
    </message>
    <message>
        <source>ANGLE OF SPINDLE</source>
        <translation>KĄT WRZECIONA</translation>
    </message>
    <message>
        <source>DATUM NUMBER</source>
        <translation>NUMER PUNKTU ZER.</translation>
    </message>
    <message>
        <source>ROUGHING DIAMETER</source>
        <translation>ŚREDNICA WSTĘPNA</translation>
    </message>
    <message>
        <source>SELECT DIA./DEPTH</source>
        <translation>WYBÓR ŚRED./GŁĘB.</translation>
    </message>
    <message>
        <source>DIAMETER</source>
        <translation>ŚREDNICA</translation>
    </message>
    <message>
        <source>SELECT POS. HEIGHT</source>
        <translation>WYBÓR WYS. POZYCJI</translation>
    </message>
    <message>
        <source>CLIMB OR UP-CUT</source>
        <translation>WSPÓŁ-/PRZECIWBIEŻNIE</translation>
    </message>
    <message>
        <source>THREADS PER STEP</source>
        <translation>ZWOJE NA KROK</translation>
    </message>
    <message>
        <source>COUNTERSINKING DEPTH</source>
        <translation>GŁĘB. POGŁĘBIENIA</translation>
    </message>
    <message>
        <source>CLEARANCE TO SIDE</source>
        <translation>ODSTĘP Z BOKU</translation>
    </message>
    <message>
        <source>DEPTH AT FRONT</source>
        <translation>GŁĘBOKOŚĆ CZOŁOWO</translation>
    </message>
    <message>
        <source>OFFSET AT FRONT</source>
        <translation>PRZESUNIĘCIE CZOŁOWO</translation>
    </message>
    <message>
        <source>COUNTERSINK PROCESS</source>
        <translation>PROCES POGŁĘBIANIA</translation>
    </message>
    <message>
        <source>TYPE OF TRAVERSE</source>
        <translation>RODZAJ PRZEJAZDU</translation>
    </message>
    <message>
        <source>TEXT POSITION</source>
        <translation>POŁOŻENIE TEKSTU</translation>
    </message>
    <message>
        <source>ALLOWANCE FOR FLOOR</source>
        <translation>NADDATEK NA DNO</translation>
    </message>
    <message>
        <source>MAX. OVERLAP</source>
        <translation>MAKS. NAKŁADANIE</translation>
    </message>
    <message>
        <source>STARTING POINT</source>
        <translation>PUNKT STARTU</translation>
    </message>
    <message>
        <source>FINISHING FEED RATE</source>
        <translation>POSUW WYKAŃCZANIA</translation>
    </message>
    <message>
        <source>END POINT 3RD AXIS</source>
        <translation>PUNKT KOŃC. 3. OSI</translation>
    </message>
    <message>
        <source>STRATEGY</source>
        <translation>STRATEGIA</translation>
    </message>
    <message>
        <source>DEPTH REFERENCE</source>
        <translation>ODNIESIENIE GŁĘB.</translation>
    </message>
    <message>
        <source>FEED RATE FACTOR</source>
        <translation>WSPÓŁCZYNNIK POSUWU</translation>
    </message>
    <message>
        <source>RPM FACTOR</source>
        <translation>WSPÓŁ. PRĘDK. OBR.</translation>
    </message>
    <message>
        <source>DIR. OF SPINDLE ROT.</source>
        <translation>KIERUNEK OBROTÓW</translation>
    </message>
    <message>
        <source>ROT.SPEED INFEED/OUT</source>
        <translation>OBROTY WEJ./WYJ.</translation>
    </message>
    <message>
        <source>ROT. SPEED DRILLING</source>
        <translation>OBROTY WIERCENIA</translation>
    </message>
    <message>
        <source>COOLANT ON</source>
        <translation>CHŁODZIWO WŁ.</translation>
    </message>
    <message>
        <source>COOLANT OFF</source>
        <translation>CHŁODZIWO WYŁ.</translation>
    </message>
    <message>
        <source>DWELL DEPTH</source>
        <translation>GŁĘBOKOŚĆ PRZERWY</translation>
    </message>
    <message>
        <source>ENGRAVING TEXT</source>
        <translation>TEKST GRAWEROWANIA</translation>
    </message>
    <message>
        <source>FEED FOR APPROACH</source>
        <translation>POSUW NAJAZDU</translation>
    </message>
    <message>
        <source>CHARACTER HEIGHT</source>
        <translation>WYSOKOŚĆ ZNAKÓW</translation>
    </message>
    <message>
        <source>SPACE FACTOR</source>
        <translation>WSPÓŁ. ODSTĘPU</translation>
    </message>
    <message>
        <source>FONT</source>
        <translation>CZCIONKA</translation>
    </message>
    <message>
        <source>TEXT LAYOUT</source>
        <translation>UKŁAD TEKSTU</translation>
    </message>
    <message>
        <source>CIRCLE RADIUS</source>
        <translation>PROMIEŃ OKRĘGU</translation>
    </message>
    <message>
        <source>MAX. TEXT LENGTH</source>
        <translation>MAKS. DŁ. TEKSTU</translation>
    </message>
    <message>
        <source>F COUNTERBORING</source>
        <translation>POSUW POGŁ. WSTECZ.</translation>
    </message>
    <message>
        <source>DEPTH OF THREAD</source>
        <translation>GŁĘBOKOŚĆ GWINTU</translation>
    </message>
    <message>
        <source>MAX. PLUNGING DEPTH</source>
        <translation>MAKS. GŁĘB. DOSUWU</translation>
    </message>
    <message>
        <source>TOTAL HOLE DEPTH</source>
        <translation>CAŁK. GŁĘB. OTWORU</translation>
    </message>
    <message>
        <source>%1: %2 needs a positive feed after it, e.g. %2 0.1</source>
        <translation>%1: po %2 musi następować dodatni posuw, np. %2 0.1</translation>
    </message>
    <message>
        <source>%1: %2 is not allowed here; enter a number</source>
        <translation>%1: %2 nie jest tu dozwolone; wprowadź liczbę</translation>
    </message>
    <message>
        <source>%1: %2 is not allowed here; allowed: a number, %3</source>
        <translation>%1: %2 nie jest tu dozwolone; dozwolone: liczba, %3</translation>
    </message>
    <message>
        <source>%1: enter a value</source>
        <translation>%1: wprowadź wartość</translation>
    </message>
    <message>
        <source>%1: the text must not contain &quot;</source>
        <translation>%1: tekst nie może zawierać &quot;</translation>
    </message>
    <message>
        <source>%1: enter axis letters separated by blanks, e.g. X Y</source>
        <translation>%1: wprowadź litery osi rozdzielone spacjami, np. X Y</translation>
    </message>
    <message>
        <source>%1: #n needs a datum number, e.g. #5</source>
        <translation>%1: #n wymaga numeru punktu zerowego, np. #5</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: &quot;%2&quot; nie jest liczbą</translation>
    </message>
    <message>
        <source>%1: enter a whole number from %2 to %3</source>
        <translation>%1: wprowadź liczbę całkowitą od %2 do %3</translation>
    </message>
    <message>
        <source>%1: %2 is outside the range %3 to %4</source>
        <translation>%1: %2 leży poza zakresem %3 do %4</translation>
    </message>
    <message>
        <source>%1 coordinate of the end point (I before the value: incremental)</source>
        <translation>Współrzędna %1 punktu końcowego (I przed wartością: przyrostowo)</translation>
    </message>
    <message>
        <source>Circle radius (negative: arc greater than 180°)</source>
        <translation>Promień okręgu (ujemny: łuk większy niż 180°)</translation>
    </message>
    <message>
        <source>Chamfer length</source>
        <translation>Długość fazy</translation>
    </message>
    <message>
        <source>Rounding radius</source>
        <translation>Promień zaokrąglenia</translation>
    </message>
    <message>
        <source>Direction of rotation (DR-: clockwise, DR+: counterclockwise)</source>
        <translation>Kierunek obrotu (DR-: zgodnie z ruchem wskazówek zegara, DR+: przeciwnie)</translation>
    </message>
    <message>
        <source>Radius compensation (RL left, RR right of the contour, R0 none)</source>
        <translation>Korekcja promienia (RL z lewej, RR z prawej strony konturu, R0 brak)</translation>
    </message>
    <message>
        <source>Feed rate (FMAX: rapid traverse, FAUTO: from TOOL CALL)</source>
        <translation>Posuw (FMAX: bieg szybki, FAUTO: z TOOL CALL)</translation>
    </message>
    <message>
        <source>Miscellaneous functions, e.g. 3 8</source>
        <translation>Funkcje dodatkowe, np. 3 8</translation>
    </message>
    <message>
        <source>Tool number or name</source>
        <translation>Numer lub nazwa narzędzia</translation>
    </message>
    <message>
        <source>Spindle axis</source>
        <translation>Oś wrzeciona</translation>
    </message>
    <message>
        <source>Spindle speed S [1/min]</source>
        <translation>Prędkość obrotowa wrzeciona S [1/min]</translation>
    </message>
    <message>
        <source>Delta length DL</source>
        <translation>Delta długości DL</translation>
    </message>
    <message>
        <source>Delta radius DR</source>
        <translation>Delta promienia DR</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a coordinate</source>
        <translation>%1: &quot;%2&quot; nie jest współrzędną</translation>
    </message>
    <message>
        <source>%1: enter a radius other than 0</source>
        <translation>%1: wprowadź promień różny od 0</translation>
    </message>
    <message>
        <source>%1: enter a positive number</source>
        <translation>%1: wprowadź liczbę dodatnią</translation>
    </message>
    <message>
        <source>%1: enter a feed rate, FMAX or FAUTO</source>
        <translation>%1: wprowadź posuw, FMAX lub FAUTO</translation>
    </message>
    <message>
        <source>%1: enter M function numbers, e.g. 3 8</source>
        <translation>%1: wprowadź numery funkcji M, np. 3 8</translation>
    </message>
    <message>
        <source>%1: enter a tool number or a name</source>
        <translation>%1: wprowadź numer lub nazwę narzędzia</translation>
    </message>
    <message>
        <source>%1: choose one of %2</source>
        <translation>%1: wybierz jedną z wartości %2</translation>
    </message>
    <message>
        <source>%1: enter at least one coordinate</source>
        <translation>%1: wprowadź co najmniej jedną współrzędną</translation>
    </message>
    <message>
        <source>Cycle
overview</source>
        <translation>Przegląd
cykli</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Powrót</translation>
    </message>
    <message>
        <source>Edit
cycle</source>
        <translation>Edytuj
cykl</translation>
    </message>
    <message>
        <source>Put the cursor on a CYCL DEF block to edit it.</source>
        <translation>Ustaw kursor na bloku CYCL DEF, aby go edytować.</translation>
    </message>
    <message>
        <source>the file is outside the NC root</source>
        <translation>plik leży poza katalogiem głównym NC</translation>
    </message>
    <message>
        <source>the file does not exist</source>
        <translation>plik nie istnieje</translation>
    </message>
    <message>
        <source>the NC root itself cannot be changed</source>
        <translation>samego katalogu głównego NC nie można zmienić</translation>
    </message>
    <message>
        <source>the file is protected</source>
        <translation>plik jest chroniony</translation>
    </message>
    <message>
        <source>a file with this name exists already</source>
        <translation>plik o tej nazwie już istnieje</translation>
    </message>
    <message>
        <source>cannot copy: {1}</source>
        <translation>nie można skopiować: {1}</translation>
    </message>
    <message>
        <source>cannot move: {1}</source>
        <translation>nie można przenieść: {1}</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a valid file name</source>
        <translation>&apos;{1}&apos; nie jest prawidłową nazwą pliku</translation>
    </message>
    <message>
        <source>cannot delete: {1}</source>
        <translation>nie można usunąć: {1}</translation>
    </message>
    <message>
        <source>cannot create the folder: {1}</source>
        <translation>nie można utworzyć folderu: {1}</translation>
    </message>
    <message>
        <source>cannot change the protection: {1}</source>
        <translation>nie można zmienić ochrony: {1}</translation>
    </message>
    <message>
        <source>{1} needs a number, not &quot;{2}&quot;</source>
        <translation>{1} wymaga liczby, a nie &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>{1} must be from {2} to {3}</source>
        <translation>{1} musi mieścić się w zakresie od {2} do {3}</translation>
    </message>
    <message>
        <source>this table has a fixed row for every entry: edit the values instead</source>
        <translation>ta tabela ma stały wiersz dla każdej pozycji: zamiast tego edytuj wartości</translation>
    </message>
    <message>
        <source>the table is full ({1}{2} to {1}{3})</source>
        <translation>tabela jest pełna ({1}{2} do {1}{3})</translation>
    </message>
    <message>
        <source>the test run stopped after {1} blocks: endless loop?</source>
        <translation>test programu zatrzymał się po {1} blokach: nieskończona pętla?</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a regular file</source>
        <translation>&apos;{1}&apos; nie jest zwykłym plikiem</translation>
    </message>
    <message>
        <source>cannot write program {1}: {2}</source>
        <translation>nie można zapisać programu {1}: {2}</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is a link: Kerf does not write through links</source>
        <translation>&apos;{1}&apos; jest dowiązaniem: Kerf nie zapisuje przez dowiązania</translation>
    </message>
    <message>
        <source>and {1} more diagnostics</source>
        <translation>i {1} dalszych komunikatów</translation>
    </message>
    <message>
        <source>overflow: the result of &apos;{1}&apos; is too large</source>
        <translation>przepełnienie: wynik &apos;{1}&apos; jest za duży</translation>
    </message>
    <message>
        <source>an expression may nest at most {1} levels</source>
        <translation>wyrażenie może być zagnieżdżone najwyżej na {1} poziomów</translation>
    </message>
    <message>
        <source>P{1}: the value is too large (overflow)</source>
        <translation>P{1}: wartość jest za duża (przepełnienie)</translation>
    </message>
    <message>
        <source>{1}{2} holds no finite number</source>
        <translation>{1}{2} nie zawiera skończonej liczby</translation>
    </message>
    <message>
        <source>a formula may nest at most {1} levels</source>
        <translation>formuła może być zagnieżdżona najwyżej na {1} poziomów</translation>
    </message>
    <message>
        <source>a string may hold at most {1} characters, not {2}</source>
        <translation>łańcuch może mieć najwyżej {1} znaków, a nie {2}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the range of the control (at most {3})</source>
        <translation>{1} = {2} jest poza zakresem sterowania (najwyżej {3})</translation>
    </message>
    <message>
        <source>Programs and MDI run only after the axes are homed (Home all); false lets a machine without reference switches run from power-on</source>
        <translation>Programy i MDI działają dopiero po zbazowaniu osi (Bazuj wszystkie); false pozwala maszynie bez wyłączników referencyjnych pracować od włączenia</translation>
    </message>
    <message>
        <source>Order of the axis in Home all: lower numbers are homed first</source>
        <translation>Kolejność osi w Bazuj wszystkie: mniejsze numery są bazowane najpierw</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; changed while it was opened: a link appeared</source>
        <translation>&apos;{1}&apos; zmienił się podczas otwierania: pojawiło się dowiązanie</translation>
    </message>
    <message>
        <source>{1} must be 0, 1 or 2 for tapping</source>
        <translation>{1} musi wynosić 0, 1 lub 2 przy gwintowaniu</translation>
    </message>
    <message>
        <source>rigid tapping needs a feed and a spindle speed</source>
        <translation>gwintowanie sztywne wymaga posuwu i prędkości wrzeciona</translation>
    </message>
    <message>
        <source>the pecks shrink below 0.001 mm before the depth I: program L</source>
        <translation>zagłębienia spadają poniżej 0,001 mm przed głębokością I: zaprogramuj L</translation>
    </message>
    <message>
        <source>the groove has no depth</source>
        <translation>rowek nie ma głębokości</translation>
    </message>
    <message>
        <source>the groove is narrower than the tool&apos;s cutting width NOSEW</source>
        <translation>rowek jest węższy niż szerokość ostrza NOSEW narzędzia</translation>
    </message>
    <message>
        <source>C is not programmed and the tool has no cutting width NOSEW</source>
        <translation>C nie jest zaprogramowane, a narzędzie nie ma szerokości ostrza NOSEW</translation>
    </message>
    <message>
        <source>the tool position is not correct for the cycle ({1})</source>
        <translation>położenie narzędzia jest nieprawidłowe dla cyklu ({1})</translation>
    </message>
    <message>
        <source>the cycle would need more than {1} moves: {2} is too small</source>
        <translation>cykl wymagałby ponad {1} ruchów: {2} jest za małe</translation>
    </message>
    <message>
        <source>the section has no length along the passes</source>
        <translation>odcinek nie ma długości w kierunku przejść</translation>
    </message>
    <message>
        <source>the thread has no length along its axis</source>
        <translation>gwint nie ma długości wzdłuż swojej osi</translation>
    </message>
    <message>
        <source>{1} leaves no thread to cut between the start and the end</source>
        <translation>{1} nie zostawia gwintu do nacięcia między początkiem a końcem</translation>
    </message>
    <message>
        <source>{1} is not a parameter of {2}</source>
        <translation>{1} nie jest parametrem {2}</translation>
    </message>
    <message>
        <source>{1} of {2} needs a value</source>
        <translation>{1} w {2} wymaga wartości</translation>
    </message>
    <message>
        <source>{1} of {2} cannot be 0</source>
        <translation>{1} w {2} nie może wynosić 0</translation>
    </message>
    <message>
        <source>{1} needs its parameter {2}</source>
        <translation>{1} wymaga swojego parametru {2}</translation>
    </message>
    <message>
        <source>{1}: M (pitch change) cannot be programmed with K (repass)</source>
        <translation>{1}: M (zmiana skoku) nie może być zaprogramowane razem z K (ponowne nacinanie)</translation>
    </message>
    <message>
        <source>{1} and {2}: one canned cycle per block</source>
        <translation>{1} i {2}: jeden cykl stały na blok</translation>
    </message>
    <message>
        <source>the start and the end of an arc are not on one circle about its centre</source>
        <translation>początek i koniec łuku nie leżą na jednym okręgu wokół jego środka</translation>
    </message>
    <message>
        <source>an arc of the profile must stay within a quarter circle</source>
        <translation>łuk profilu musi mieścić się w ćwiartce okręgu</translation>
    </message>
    <message>
        <source>label N{1} of the profile is not in the program</source>
        <translation>etykiety N{1} profilu nie ma w programie</translation>
    </message>
    <message>
        <source>the profile ends (E) before it starts (S)</source>
        <translation>profil kończy się (E) przed swoim początkiem (S)</translation>
    </message>
    <message>
        <source>a profile holds no high-level blocks</source>
        <translation>profil nie zawiera bloków języka wysokiego poziomu</translation>
    </message>
    <message>
        <source>{1} is not allowed in a profile</source>
        <translation>{1} jest niedozwolone w profilu</translation>
    </message>
    <message>
        <source>the profile has more than 10000 elements</source>
        <translation>profil ma ponad 10000 elementów</translation>
    </message>
    <message>
        <source>this machine has no axis {1}</source>
        <translation>ta maszyna nie ma osi {1}</translation>
    </message>
    <message>
        <source>MACHINING OPERATION</source>
        <translation>ZAKRES OBROBKI</translation>
    </message>
    <message>
        <source>CORNER RADIUS</source>
        <translation>PROMIEN NAROZA</translation>
    </message>
    <message>
        <source>WORKPIECE BLANK DIA.</source>
        <translation>ŚREDNICA PÓŁFABRYKATU</translation>
    </message>
    <message>
        <source>CIRCLE DIAMETER</source>
        <translation>ŚREDNICA OKRĘGU</translation>
    </message>
    <message>
        <source>ANGULAR LENGTH</source>
        <translation>DŁUGOŚĆ KĄTOWA</translation>
    </message>
    <message>
        <source>INFEED FOR FINISHING</source>
        <translation>DOSUW OBR. WYKAŃCZ.</translation>
    </message>
    <message>
        <source>PLUNGE</source>
        <translation>WCIĘCIE</translation>
    </message>
    <message>
        <source>ALLOWANCE FOR SIDE</source>
        <translation>NADDATEK NA BOK</translation>
    </message>
    <message>
        <source>WORKPC. BLANK SIDE 1</source>
        <translation>PÓŁFABRYKAT BOK 1</translation>
    </message>
    <message>
        <source>WORKPC. BLANK SIDE 2</source>
        <translation>PÓŁFABRYKAT BOK 2</translation>
    </message>
    <message>
        <source>APPROACH POSITION</source>
        <translation>POZYCJA DOSUWU</translation>
    </message>
    <message>
        <source>FEED RATE REFERENCE</source>
        <translation>ODNIESIENIE POSUWU</translation>
    </message>
    <message>
        <source>REF-CIRCLE DIAMETER</source>
        <translation>ŚREDNICA OKRĘGU ODN.</translation>
    </message>
    <message>
        <source>NUMBER OF CORNERS</source>
        <translation>LICZBA NAROŻY</translation>
    </message>
    <message>
        <source>REFERENCE CIRCLE</source>
        <translation>OKRĄG ODNIESIENIA</translation>
    </message>
    <message>
        <source>POCKET POSITION</source>
        <translation>POŁOŻENIE KIESZENI</translation>
    </message>
    <message>
        <source>SLOT LENGTH</source>
        <translation>DŁUGOŚĆ ROWKA</translation>
    </message>
    <message>
        <source>SLOT WIDTH</source>
        <translation>SZEROKOŚĆ ROWKA</translation>
    </message>
    <message>
        <source>SLOT POSITION</source>
        <translation>POŁOŻENIE ROWKA</translation>
    </message>
    <message>
        <source>REF. SLOT POSITION</source>
        <translation>ODN. POŁOŻENIA ROWKA</translation>
    </message>
    <message>
        <source>RADIUS / CHAMFER</source>
        <translation>PROMIEŃ / FAZKA</translation>
    </message>
    <message>
        <source>STUD POSITION</source>
        <translation>POŁOŻENIE CZOPU</translation>
    </message>
    <message>
        <source>FINISHED PART DIA.</source>
        <translation>ŚREDNICA GOTOWEJ CZ.</translation>
    </message>
    <message>
        <source>Corner radius (0: tool radius)</source>
        <translation>Promień naroża (0: promień narzędzia)</translation>
    </message>
    <message>
        <source>RECTANGULAR POCKET</source>
        <translation>KIESZEN PROSTOKATNA</translation>
    </message>
    <message>
        <source>Circle diameter</source>
        <translation>Średnica okręgu</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 helical)</source>
        <translation>Strategia wcięcia (0 pionowo, 1 po linii śrubowej)</translation>
    </message>
    <message>
        <source>cycle {1}: vertical plunging (Q366 = 0) needs a tool whose ANGLE is 0 or 90</source>
        <translation>cykl {1}: wcięcie pionowe (Q366 = 0) wymaga narzędzia z ANGLE 0 lub 90</translation>
    </message>
    <message>
        <source>CIRCULAR POCKET</source>
        <translation>KIESZEN OKRAGLA</translation>
    </message>
    <message>
        <source>Slot length</source>
        <translation>Długość rowka</translation>
    </message>
    <message>
        <source>Slot width</source>
        <translation>Szerokość rowka</translation>
    </message>
    <message>
        <source>Slot position (0 centre, 1 left end, 2 centre of the left arc, 3 centre of the right arc, 4 right end)</source>
        <translation>Położenie rowka (0 środek, 1 lewy koniec, 2 środek lewego łuku, 3 środek prawego łuku, 4 prawy koniec)</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width Q219 is larger than its length Q218</source>
        <translation>cykl {1}: szerokość rowka Q219 jest większa niż jego długość Q218</translation>
    </message>
    <message>
        <source>SLOT MILLING</source>
        <translation>FREZOWANIE ROWKOW</translation>
    </message>
    <message>
        <source>Reference of the slot position (0 centre Q216/Q217, 1 start arc, 2 middle, 3 end arc at the tool position)</source>
        <translation>Odniesienie położenia rowka (0 środek Q216/Q217, 1 łuk początkowy, 2 środek, 3 łuk końcowy w pozycji narzędzia)</translation>
    </message>
    <message>
        <source>Angular length of the slot</source>
        <translation>Długość kątowa rowka</translation>
    </message>
    <message>
        <source>Stepping angle between repetitions</source>
        <translation>Krok kątowy między powtórzeniami</translation>
    </message>
    <message>
        <source>Number of repetitions</source>
        <translation>Liczba powtórzeń</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width Q219 must be smaller than the pitch circle diameter Q375</source>
        <translation>cykl {1}: szerokość rowka Q219 musi być mniejsza niż średnica okręgu podziałowego Q375</translation>
    </message>
    <message>
        <source>cycle {1}: the angular length Q248 closes the slot on itself</source>
        <translation>cykl {1}: długość kątowa Q248 zamyka rowek sam w sobie</translation>
    </message>
    <message>
        <source>CIRCULAR SLOT</source>
        <translation>OKRAGLY ROWEK</translation>
    </message>
    <message>
        <source>Workpiece blank side length 1</source>
        <translation>Długość boku 1 półfabrykatu</translation>
    </message>
    <message>
        <source>Workpiece blank side length 2</source>
        <translation>Długość boku 2 półfabrykatu</translation>
    </message>
    <message>
        <source>Corner radius (+) or chamfer (-)</source>
        <translation>Promień naroża (+) lub fazka (-)</translation>
    </message>
    <message>
        <source>Approach position (0 right of the stud, 1-4 corners)</source>
        <translation>Pozycja dosuwu (0 na prawo od czopu, 1-4 naroża)</translation>
    </message>
    <message>
        <source>cycle {1}: the workpiece blank is smaller than the finished part</source>
        <translation>cykl {1}: półfabrykat jest mniejszy niż gotowa część</translation>
    </message>
    <message>
        <source>RECTANGULAR STUD</source>
        <translation>CZOP PROSTOKATNY</translation>
    </message>
    <message>
        <source>Finished part diameter</source>
        <translation>Średnica gotowej części</translation>
    </message>
    <message>
        <source>Workpiece blank diameter</source>
        <translation>Średnica półfabrykatu</translation>
    </message>
    <message>
        <source>CIRCULAR STUD</source>
        <translation>CZOP OKRAGLY</translation>
    </message>
    <message>
        <source>Reference circle (0 inscribed, 1 circumscribed)</source>
        <translation>Okrąg odniesienia (0 wpisany, 1 opisany)</translation>
    </message>
    <message>
        <source>Reference circle diameter</source>
        <translation>Średnica okręgu odniesienia</translation>
    </message>
    <message>
        <source>Number of corners</source>
        <translation>Liczba naroży</translation>
    </message>
    <message>
        <source>Angle of the first corner</source>
        <translation>Kąt pierwszego naroża</translation>
    </message>
    <message>
        <source>cycle {1}: a polygon needs at least 3 corners (Q572)</source>
        <translation>cykl {1}: wielokąt wymaga co najmniej 3 naroży (Q572)</translation>
    </message>
    <message>
        <source>cycle {1}: the corner radius or chamfer Q220 is too large for the sides of the polygon</source>
        <translation>cykl {1}: promień naroża lub fazka Q220 jest za duża dla boków wielokąta</translation>
    </message>
    <message>
        <source>POLYGON STUD</source>
        <translation>CZOP WIELOKATNY</translation>
    </message>
    <message>
        <source>cycle {1} needs a tool with a radius greater than 0</source>
        <translation>cykl {1} wymaga narzędzia o promieniu większym od 0</translation>
    </message>
    <message>
        <source>cycle {1}: helical or reciprocating plunging (Q366) needs the plunge angle ANGLE of the tool</source>
        <translation>cykl {1}: wcięcie po linii śrubowej lub ruchem wahadłowym (Q366) wymaga kąta wcięcia ANGLE narzędzia</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is too large for the programmed size and finishing allowance</source>
        <translation>cykl {1}: narzędzie jest za duże dla zaprogramowanego wymiaru i naddatku na obróbkę wykańczającą</translation>
    </message>
    <message>
        <source>cycle {1}: no room for the helical plunge: the helix needs a diameter of twice the tool diameter</source>
        <translation>cykl {1}: brak miejsca na wcięcie po linii śrubowej: linia śrubowa wymaga podwójnej średnicy narzędzia</translation>
    </message>
    <message>
        <source>cycle {1}: no room for reciprocating plunging: it needs a length of twice the tool diameter</source>
        <translation>cykl {1}: brak miejsca na wcięcie ruchem wahadłowym: wymaga długości podwójnej średnicy narzędzia</translation>
    </message>
    <message>
        <source>Machining operation (0 roughing and finishing, 1 roughing, 2 finishing)</source>
        <translation>Zakres obróbki (0 zgrubna i wykańczająca, 1 zgrubna, 2 wykańczająca)</translation>
    </message>
    <message>
        <source>First side length</source>
        <translation>Długość pierwszego boku</translation>
    </message>
    <message>
        <source>Second side length</source>
        <translation>Długość drugiego boku</translation>
    </message>
    <message>
        <source>Finishing allowance for the side</source>
        <translation>Naddatek na obróbkę wykańczającą boku</translation>
    </message>
    <message>
        <source>Position (0 centre, 1 lower left, 2 lower right, 3 upper right, 4 upper left corner)</source>
        <translation>Położenie (0 środek, 1 naroże lewe dolne, 2 prawe dolne, 3 prawe górne, 4 lewe górne)</translation>
    </message>
    <message>
        <source>Infeed for finishing (0: one infeed)</source>
        <translation>Dosuw przy obróbce wykańczającej (0: jeden dosuw)</translation>
    </message>
    <message>
        <source>Feed rate reference (0 tool centre, 1 cutting edge when side finishing, 2 also floor finishing, 3 always)</source>
        <translation>Odniesienie posuwu (0 środek narzędzia, 1 ostrze przy wykańczaniu boku, 2 także dna, 3 zawsze)</translation>
    </message>
    <message>
        <source>Code number asked before machine parameters may be edited</source>
        <translation>Kod liczbowy wymagany przed edycją parametrów maszyny</translation>
    </message>
    <message>
        <source>the profile has no length</source>
        <translation>profil nie ma długości</translation>
    </message>
    <message>
        <source>the profile cannot be copied at the distance of a pass: it is too narrow</source>
        <translation>profilu nie można skopiować w odległości przejścia: jest zbyt wąski</translation>
    </message>
    <message>
        <source>the profile runs back against the passes (an undercut): the tool cannot reach it</source>
        <translation>profil cofa się wbrew przejściom (podcięcie): narzędzie go nie osiągnie</translation>
    </message>
    <message>
        <source>the section runs back under the material</source>
        <translation>odcinek cofa się pod materiał</translation>
    </message>
    <message>
        <source>{1} cannot make an arc to this end point</source>
        <translation>{1} nie może utworzyć łuku do tego punktu końcowego</translation>
    </message>
    <message>
        <source>a profile has one raw-stock part (one G00)</source>
        <translation>profil ma jedną część półfabrykatu (jedno G00)</translation>
    </message>
    <message>
        <source>the G00 block starts the raw-stock profile: it needs its point</source>
        <translation>blok G00 rozpoczyna profil półfabrykatu: potrzebuje swojego punktu</translation>
    </message>
    <message>
        <source>cycle parameters belong to a cycle block (G2xx, G4xx ...)</source>
        <translation>parametry cyklu należą do bloku cyklu (G2xx, G4xx ...)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not allowed in this block</source>
        <translation>&apos;{1}&apos; nie jest dozwolone w tym bloku</translation>
    </message>
    <message>
        <source>program name expected after &apos;%&apos;</source>
        <translation>oczekiwano nazwy programu po &apos;%&apos;</translation>
    </message>
    <message>
        <source>P0{1} expected</source>
        <translation>oczekiwano P0{1}</translation>
    </message>
    <message>
        <source>label number expected</source>
        <translation>oczekiwano numeru etykiety</translation>
    </message>
    <message>
        <source>two path functions in one block</source>
        <translation>dwie funkcje toru w jednym bloku</translation>
    </message>
    <message>
        <source>G70/G71 belong to the program header &apos;%NAME&apos;</source>
        <translation>G70/G71 należą do nagłówka programu &apos;%NAME&apos;</translation>
    </message>
    <message>
        <source>G{1} and G{2} cannot share a block</source>
        <translation>G{1} i G{2} nie mogą być w jednym bloku</translation>
    </message>
    <message>
        <source>value expected after &apos;{1}&apos;</source>
        <translation>oczekiwano wartości po &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>a label has no repeat count</source>
        <translation>etykieta nie ma liczby powtórzeń</translation>
    </message>
    <message>
        <source>label number expected (G98 L1)</source>
        <translation>oczekiwano numeru etykiety (G98 L1)</translation>
    </message>
    <message>
        <source>tool number expected (T)</source>
        <translation>oczekiwano numeru narzędzia (T)</translation>
    </message>
    <message>
        <source>the plane belongs to G30</source>
        <translation>płaszczyzna należy do G30</translation>
    </message>
    <message>
        <source>R expected after G{1}</source>
        <translation>oczekiwano R po G{1}</translation>
    </message>
    <message>
        <source>unknown G function G{1}</source>
        <translation>nieznana funkcja G G{1}</translation>
    </message>
    <message>
        <source>G17/G18/G19 belong to a tool call (T) or a blank (G30)</source>
        <translation>G17/G18/G19 należą do wywołania narzędzia (T) lub półfabrykatu (G30)</translation>
    </message>
    <message>
        <source>no path function (G00, G01, G02 ...) is active</source>
        <translation>żadna funkcja toru (G00, G01, G02 ...) nie jest aktywna</translation>
    </message>
    <message>
        <source>a feed rate F is not allowed with rapid G{1}</source>
        <translation>posuw F nie jest dozwolony przy szybkim przesuwie G{1}</translation>
    </message>
    <message>
        <source>{1} expected after G{2}</source>
        <translation>oczekiwano {1} po G{2}</translation>
    </message>
    <message>
        <source>program name expected (P01 &quot;NAME&quot;)</source>
        <translation>oczekiwano nazwy programu (P01 &quot;NAME&quot;)</translation>
    </message>
    <message>
        <source>contour labels expected (P01 1)</source>
        <translation>oczekiwano etykiet konturu (P01 1)</translation>
    </message>
    <message>
        <source>text after the block end &apos;*&apos;</source>
        <translation>tekst po końcu bloku &apos;*&apos;</translation>
    </message>
    <message>
        <source>closing &apos;&quot;&apos; missing</source>
        <translation>brak zamykającego &apos;&quot;&apos;</translation>
    </message>
    <message>
        <source>number expected after &apos;{1}&apos;</source>
        <translation>oczekiwano liczby po &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>repeat count expected after &apos;,&apos;</source>
        <translation>oczekiwano liczby powtórzeń po &apos;,&apos;</translation>
    </message>
    <message>
        <source>cycle {1}: the stepping angle Q247 must be at least 5 degrees</source>
        <translation>cykl {1}: krok kąta Q247 musi wynosić co najmniej 5 stopni</translation>
    </message>
    <message>
        <source>cycle {1}: the touch points give no circle</source>
        <translation>cykl {1}: punkty próbkowania nie tworzą okręgu</translation>
    </message>
    <message>
        <source>1st touch point, main axis</source>
        <translation>1. punkt próbkowania, oś główna</translation>
    </message>
    <message>
        <source>1st touch point, secondary axis</source>
        <translation>1. punkt próbkowania, oś pomocnicza</translation>
    </message>
    <message>
        <source>Spacing of touch points 1 and 2 in the main axis</source>
        <translation>Odstęp punktów próbkowania 1 i 2 w osi głównej</translation>
    </message>
    <message>
        <source>3rd touch point, main axis</source>
        <translation>3. punkt próbkowania, oś główna</translation>
    </message>
    <message>
        <source>3rd touch point, secondary axis</source>
        <translation>3. punkt próbkowania, oś pomocnicza</translation>
    </message>
    <message>
        <source>Spacing of touch points 3 and 4 in the secondary axis</source>
        <translation>Odstęp punktów próbkowania 3 i 4 w osi pomocniczej</translation>
    </message>
    <message>
        <source>Basic rotation too: 0 no, 1 yes</source>
        <translation>Również obrót podstawowy: 0 nie, 1 tak</translation>
    </message>
    <message>
        <source>Corner, main axis</source>
        <translation>Naroże, oś główna</translation>
    </message>
    <message>
        <source>Corner, secondary axis</source>
        <translation>Naroże, oś pomocnicza</translation>
    </message>
    <message>
        <source>Corner: 1 (-M -S), 2 (+M -S), 3 (+M +S), 4 (-M +S)</source>
        <translation>Naroże: 1 (-M -S), 2 (+M -S), 3 (+M +S), 4 (-M +S)</translation>
    </message>
    <message>
        <source>Bolt-circle centre, main axis</source>
        <translation>Środek okręgu otworów, oś główna</translation>
    </message>
    <message>
        <source>Bolt-circle centre, secondary axis</source>
        <translation>Środek okręgu otworów, oś pomocnicza</translation>
    </message>
    <message>
        <source>Nominal bolt-circle diameter</source>
        <translation>Nominalna średnica okręgu otworów</translation>
    </message>
    <message>
        <source>Polar angle of the 1st hole centre</source>
        <translation>Kąt biegunowy środka 1. otworu</translation>
    </message>
    <message>
        <source>Polar angle of the 2nd hole centre</source>
        <translation>Kąt biegunowy środka 2. otworu</translation>
    </message>
    <message>
        <source>Polar angle of the 3rd hole centre</source>
        <translation>Kąt biegunowy środka 3. otworu</translation>
    </message>
    <message>
        <source>cycle {1}: the two edges are parallel</source>
        <translation>cykl {1}: obie krawędzie są równoległe</translation>
    </message>
    <message>
        <source>cycle {1}: the hole centres give no circle</source>
        <translation>cykl {1}: środki otworów nie tworzą okręgu</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE CORNER</source>
        <translation>PUNKT ODNIESIENIA NAROŻE NA ZEWNĄTRZ</translation>
    </message>
    <message>
        <source>DATUM INSIDE CORNER</source>
        <translation>PUNKT ODNIESIENIA NAROŻE WEWNĄTRZ</translation>
    </message>
    <message>
        <source>DATUM CIRCLE CENTER</source>
        <translation>PUNKT ODNIESIENIA ŚRODEK OKRĘGU OTWORÓW</translation>
    </message>
    <message>
        <source>Nominal intersection, main axis</source>
        <translation>Nominalny punkt przecięcia, oś główna</translation>
    </message>
    <message>
        <source>Nominal intersection, secondary axis</source>
        <translation>Nominalny punkt przecięcia, oś pomocnicza</translation>
    </message>
    <message>
        <source>Nominal position in the tool axis: the measuring height</source>
        <translation>Pozycja nominalna w osi narzędzia: wysokość pomiaru</translation>
    </message>
    <message>
        <source>Tolerance of the 1st edge along its normal, e.g. &quot;0.1-0.1&quot;</source>
        <translation>Tolerancja 1. krawędzi wzdłuż jej normalnej, np. &quot;0.1-0.1&quot;</translation>
    </message>
    <message>
        <source>Nominal angle of the 1st line</source>
        <translation>Kąt nominalny 1. prostej</translation>
    </message>
    <message>
        <source>Probing direction of the 1st line: +1 angle + 90, -1 - 90</source>
        <translation>Kierunek próbkowania 1. prostej: +1 kąt + 90, -1 - 90</translation>
    </message>
    <message>
        <source>Intersection to the 1st touch point of the 1st line</source>
        <translation>Odległość od punktu przecięcia do 1. punktu próbkowania 1. prostej</translation>
    </message>
    <message>
        <source>Intersection to the 2nd touch point of the 1st line</source>
        <translation>Odległość od punktu przecięcia do 2. punktu próbkowania 1. prostej</translation>
    </message>
    <message>
        <source>Tolerance of the 2nd edge along its normal</source>
        <translation>Tolerancja 2. krawędzi wzdłuż jej normalnej</translation>
    </message>
    <message>
        <source>Nominal angle of the 2nd line</source>
        <translation>Kąt nominalny 2. prostej</translation>
    </message>
    <message>
        <source>Probing direction of the 2nd line: +1 angle + 90, -1 - 90</source>
        <translation>Kierunek próbkowania 2. prostej: +1 kąt + 90, -1 - 90</translation>
    </message>
    <message>
        <source>Intersection to the 1st touch point of the 2nd line</source>
        <translation>Odległość od punktu przecięcia do 1. punktu próbkowania 2. prostej</translation>
    </message>
    <message>
        <source>Intersection to the 2nd touch point of the 2nd line</source>
        <translation>Odległość od punktu przecięcia do 2. punktu próbkowania 2. prostej</translation>
    </message>
    <message>
        <source>Plane of the angles: 1 YZ, 2 ZX, 3 XY</source>
        <translation>Płaszczyzna kątów: 1 YZ, 2 ZX, 3 XY</translation>
    </message>
    <message>
        <source>Clearance height: -1 never, 0 cycle, 1 each edge, 2 each touch point</source>
        <translation>Bezpieczna wysokość: -1 nigdy, 0 cykl, 1 każda krawędź, 2 każdy punkt próbkowania</translation>
    </message>
    <message>
        <source>Tolerance error: 0 nothing, 1 stop, 2 stop on scrap only</source>
        <translation>Błąd tolerancji: 0 nic, 1 stop, 2 stop tylko przy wyrobie wadliwym</translation>
    </message>
    <message>
        <source>Align rotary axes: 0 no, 1 MOVE, 2 TURN</source>
        <translation>Ustawienie osi obrotowych: 0 nie, 1 MOVE, 2 TURN</translation>
    </message>
    <message>
        <source>Transfer position into the active preset: 0 no, 1 yes</source>
        <translation>Przejęcie pozycji do aktywnego punktu odniesienia: 0 nie, 1 tak</translation>
    </message>
    <message>
        <source>Accept rotation: 0 no, 1/3/5 basic rotation from edge 1/2/mean</source>
        <translation>Przejęcie obrotu: 0 nie, 1/3/5 obrót podstawowy z krawędzi 1/2/średniej</translation>
    </message>
    <message>
        <source>cycle {1}: aligning the rotary axes (Q1126) needs the rotation accepted (Q1121)</source>
        <translation>cykl {1}: ustawienie osi obrotowych (Q1126) wymaga przejęcia obrotu (Q1121)</translation>
    </message>
    <message>
        <source>cycle {1}: this machine has no rotary table axis to correct the rotation with</source>
        <translation>cykl {1}: ta maszyna nie ma osi stołu obrotowego do skorygowania obrotu</translation>
    </message>
    <message>
        <source>cycle {1}: tolerance QS{2} = &quot;{3}&quot; is not &quot;upper-lower&quot; or a number</source>
        <translation>cykl {1}: tolerancja QS{2} = &quot;{3}&quot; nie jest ani &quot;górna-dolna&quot;, ani liczbą</translation>
    </message>
    <message>
        <source>cycle {1}: tolerance exceeded ({2})</source>
        <translation>cykl {1}: tolerancja przekroczona ({2})</translation>
    </message>
    <message>
        <source>PROBING INTERSECTION</source>
        <translation>PRÓBKOWANIE PUNKTU PRZECIĘCIA</translation>
    </message>
    <message>
        <source>2nd touch point, main axis</source>
        <translation>2. punkt próbkowania, oś główna</translation>
    </message>
    <message>
        <source>2nd touch point, secondary axis</source>
        <translation>2. punkt próbkowania, oś pomocnicza</translation>
    </message>
    <message>
        <source>Preset rotation angle: angle of the reference line</source>
        <translation>Nastawa kąta obrotu: kąt prostej odniesienia</translation>
    </message>
    <message>
        <source>BASIC ROTATION</source>
        <translation>OBRÓT PODSTAWOWY</translation>
    </message>
    <message>
        <source>Centre in the main axis</source>
        <translation>Środek w osi głównej</translation>
    </message>
    <message>
        <source>Centre in the secondary axis</source>
        <translation>Środek w osi pomocniczej</translation>
    </message>
    <message>
        <source>Side length parallel to the main axis</source>
        <translation>Długość boku równoległego do osi głównej</translation>
    </message>
    <message>
        <source>Side length parallel to the secondary axis</source>
        <translation>Długość boku równoległego do osi pomocniczej</translation>
    </message>
    <message>
        <source>Touch point, main axis</source>
        <translation>Punkt próbkowania, oś główna</translation>
    </message>
    <message>
        <source>Touch point, secondary axis</source>
        <translation>Punkt próbkowania, oś pomocnicza</translation>
    </message>
    <message>
        <source>Touch point, nominal surface in the tool axis</source>
        <translation>Punkt próbkowania, powierzchnia nominalna w osi narzędzia</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main, 2 secondary, 3 tool axis</source>
        <translation>Oś pomiarowa: 1 główna, 2 pomocnicza, 3 oś narzędzia</translation>
    </message>
    <message>
        <source>New datum in the measuring axis</source>
        <translation>Nowy punkt odniesienia w osi pomiarowej</translation>
    </message>
    <message>
        <source>DATUM INSIDE RECTANGLE</source>
        <translation>PUNKT ODNIESIENIA PROSTOKĄT WEWNĄTRZ</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE RECTANGLE</source>
        <translation>PUNKT ODNIESIENIA PROSTOKĄT NA ZEWNĄTRZ</translation>
    </message>
    <message>
        <source>DATUM INSIDE CIRCLE</source>
        <translation>PUNKT ODNIESIENIA OKRĄG WEWNĄTRZ</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE CIRCLE</source>
        <translation>PUNKT ODNIESIENIA OKRĄG NA ZEWNĄTRZ</translation>
    </message>
    <message>
        <source>DATUM IN TS AXIS</source>
        <translation>PUNKT ODNIESIENIA W OSI SONDY</translation>
    </message>
    <message>
        <source>DATUM IN ONE AXIS</source>
        <translation>PUNKT ODNIESIENIA W JEDNEJ OSI</translation>
    </message>
    <message>
        <source>cycle {1}: define the measured-value transfer (Q303)</source>
        <translation>cykl {1}: zdefiniuj przekazanie wartości pomiaru (Q303)</translation>
    </message>
    <message>
        <source>Nominal centre, main axis</source>
        <translation>Środek nominalny, oś główna</translation>
    </message>
    <message>
        <source>Nominal centre, secondary axis</source>
        <translation>Środek nominalny, oś pomocnicza</translation>
    </message>
    <message>
        <source>Maximum permitted diameter (0: not monitored)</source>
        <translation>Maksymalna dopuszczalna średnica (0: bez nadzoru)</translation>
    </message>
    <message>
        <source>Minimum permitted diameter</source>
        <translation>Minimalna dopuszczalna średnica</translation>
    </message>
    <message>
        <source>Centre tolerance, main axis (0: not monitored)</source>
        <translation>Tolerancja środka, oś główna (0: bez nadzoru)</translation>
    </message>
    <message>
        <source>Centre tolerance, secondary axis</source>
        <translation>Tolerancja środka, oś pomocnicza</translation>
    </message>
    <message>
        <source>Compatibility only, no effect</source>
        <translation>Tylko dla zgodności, bez działania</translation>
    </message>
    <message>
        <source>Starting point, main axis</source>
        <translation>Punkt startu, oś główna</translation>
    </message>
    <message>
        <source>Starting point, secondary axis</source>
        <translation>Punkt startu, oś pomocnicza</translation>
    </message>
    <message>
        <source>Offset before the second measurement (0: none)</source>
        <translation>Przesunięcie przed drugim pomiarem (0: brak)</translation>
    </message>
    <message>
        <source>Nominal length</source>
        <translation>Długość nominalna</translation>
    </message>
    <message>
        <source>Maximum permitted length (0: not monitored)</source>
        <translation>Maksymalna dopuszczalna długość (0: bez nadzoru)</translation>
    </message>
    <message>
        <source>Minimum permitted length</source>
        <translation>Minimalna dopuszczalna długość</translation>
    </message>
    <message>
        <source>Nominal side length parallel to the main axis</source>
        <translation>Nominalna długość boku równoległego do osi głównej</translation>
    </message>
    <message>
        <source>Nominal side length parallel to the secondary axis</source>
        <translation>Nominalna długość boku równoległego do osi pomocniczej</translation>
    </message>
    <message>
        <source>Maximum length of side 1 (0: not monitored)</source>
        <translation>Maksymalna długość boku 1 (0: bez nadzoru)</translation>
    </message>
    <message>
        <source>Minimum length of side 1</source>
        <translation>Minimalna długość boku 1</translation>
    </message>
    <message>
        <source>Maximum length of side 2 (0: not monitored)</source>
        <translation>Maksymalna długość boku 2 (0: bez nadzoru)</translation>
    </message>
    <message>
        <source>Minimum length of side 2</source>
        <translation>Minimalna długość boku 2</translation>
    </message>
    <message>
        <source>Maximum permitted value (0 with Q289 = 0: not monitored)</source>
        <translation>Maksymalna dopuszczalna wartość (0 przy Q289 = 0: bez nadzoru)</translation>
    </message>
    <message>
        <source>Minimum permitted value</source>
        <translation>Minimalna dopuszczalna wartość</translation>
    </message>
    <message>
        <source>MEASURE ANGLE</source>
        <translation>POMIAR KĄTA</translation>
    </message>
    <message>
        <source>MEASURE RECTANGLE INSIDE</source>
        <translation>POMIAR PROSTOKĄTA WEWNĄTRZ</translation>
    </message>
    <message>
        <source>MEASURE RECTANGLE OUTSIDE</source>
        <translation>POMIAR PROSTOKĄTA NA ZEWNĄTRZ</translation>
    </message>
    <message>
        <source>MEASURE COORDINATE</source>
        <translation>POMIAR WSPÓŁRZĘDNEJ</translation>
    </message>
    <message>
        <source>MEASURE HOLE</source>
        <translation>POMIAR OTWORU</translation>
    </message>
    <message>
        <source>MEASURE CIRCLE OUTSIDE</source>
        <translation>POMIAR OKRĘGU NA ZEWNĄTRZ</translation>
    </message>
    <message>
        <source>MEASURE INSIDE WIDTH</source>
        <translation>POMIAR SZEROKOŚCI WEWNĄTRZ</translation>
    </message>
    <message>
        <source>MEASURE RIDGE WIDTH</source>
        <translation>POMIAR SZEROKOŚCI MOSTKA</translation>
    </message>
    <message>
        <source>cycle {1}: stylus already deflected</source>
        <translation>cykl {1}: trzpień już wychylony</translation>
    </message>
    <message>
        <source>cycle {1}: touch point not reached within the measuring path DIST = {2} mm</source>
        <translation>cykl {1}: nie osiągnięto punktu próbkowania w obrębie drogi pomiarowej DIST = {2} mm</translation>
    </message>
    <message>
        <source>Measuring height: ball centre in the tool axis</source>
        <translation>Wysokość pomiaru: środek kulki w osi narzędzia</translation>
    </message>
    <message>
        <source>Set-up clearance, added to SET_UP of the probe table</source>
        <translation>Odstęp bezpieczeństwa, dodawany do SET_UP z tabeli sond</translation>
    </message>
    <message>
        <source>Clearance height: no collision with workpiece or fixtures</source>
        <translation>Bezpieczna wysokość: brak kolizji z przedmiotem lub mocowaniem</translation>
    </message>
    <message>
        <source>Move to clearance height between points: 0 no, 1 yes</source>
        <translation>Przejazd na bezpieczną wysokość między punktami: 0 nie, 1 tak</translation>
    </message>
    <message>
        <source>Number in table: 0 sets the display (active preset)</source>
        <translation>Numer w tabeli: 0 ustawia wskazanie (aktywny punkt odniesienia)</translation>
    </message>
    <message>
        <source>Measured-value transfer: 0 datum table, 1 preset table</source>
        <translation>Przekazanie wartości pomiaru: 0 tabela punktów zerowych, 1 tabela punktów odniesienia</translation>
    </message>
    <message>
        <source>New datum in the main axis</source>
        <translation>Nowy punkt odniesienia w osi głównej</translation>
    </message>
    <message>
        <source>New datum in the secondary axis</source>
        <translation>Nowy punkt odniesienia w osi pomocniczej</translation>
    </message>
    <message>
        <source>New datum in the tool axis</source>
        <translation>Nowy punkt odniesienia w osi narzędzia</translation>
    </message>
    <message>
        <source>Probe in the tool axis too: 0 no, 1 yes</source>
        <translation>Próbkowanie również w osi narzędzia: 0 nie, 1 tak</translation>
    </message>
    <message>
        <source>Tool-axis touch point, main axis</source>
        <translation>Punkt próbkowania w osi narzędzia, oś główna</translation>
    </message>
    <message>
        <source>Tool-axis touch point, secondary axis</source>
        <translation>Punkt próbkowania w osi narzędzia, oś pomocnicza</translation>
    </message>
    <message>
        <source>Tool-axis touch point, nominal surface in the tool axis</source>
        <translation>Punkt próbkowania w osi narzędzia, powierzchnia nominalna w osi narzędzia</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main axis, 2 secondary axis</source>
        <translation>Oś pomiarowa: 1 oś główna, 2 oś pomocnicza</translation>
    </message>
    <message>
        <source>Traverse direction toward the workpiece: -1 or +1</source>
        <translation>Kierunek przemieszczenia w stronę przedmiotu: -1 lub +1</translation>
    </message>
    <message>
        <source>Starting angle: main axis to touch point 1</source>
        <translation>Kąt startu: od osi głównej do punktu próbkowania 1</translation>
    </message>
    <message>
        <source>Stepping angle between touch points (sign = direction)</source>
        <translation>Krok kąta między punktami próbkowania (znak = kierunek)</translation>
    </message>
    <message>
        <source>Number of touch points in the plane: 3 or 4</source>
        <translation>Liczba punktów próbkowania w płaszczyźnie: 3 lub 4</translation>
    </message>
    <message>
        <source>Path between points: 0 straight line, 1 arc</source>
        <translation>Tor między punktami: 0 prosta, 1 łuk</translation>
    </message>
    <message>
        <source>Measuring log: 0 none, 1 write TCHPRnnn.TXT, 2 also stop</source>
        <translation>Protokół pomiaru: 0 brak, 1 zapis TCHPRnnn.TXT, 2 także zatrzymanie</translation>
    </message>
    <message>
        <source>PGM stop on tolerance error: 0 no, 1 yes</source>
        <translation>Stop PGM przy błędzie tolerancji: 0 nie, 1 tak</translation>
    </message>
    <message>
        <source>Tool for monitoring: 0 none</source>
        <translation>Narzędzie do nadzoru: 0 brak</translation>
    </message>
    <message>
        <source>PROBE expected after TCH</source>
        <translation>po TCH oczekiwano PROBE</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: call the touch probe with TOOL CALL first (it defines the probe axis)</source>
        <translation>cykl próbkowania {1}: najpierw wywołaj sondę przez TOOL CALL (określa ona oś sondy)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: probe {2} is not in tchprobe.tp</source>
        <translation>cykl próbkowania {1}: sondy {2} nie ma w tchprobe.tp</translation>
    </message>
    <message>
        <source>touch probe cycle {1} is not supported yet</source>
        <translation>cykl próbkowania {1} nie jest jeszcze obsługiwany</translation>
    </message>
    <message>
        <source>{1}: Q{2} is PREDEF but GLOBAL DEF 120 gives no value</source>
        <translation>{1}: Q{2} to PREDEF, ale GLOBAL DEF 120 nie podaje wartości</translation>
    </message>
    <message>
        <source>{1}: probing is not possible while a coordinate transformation is active (cycles 7, 8, 10, 11, 26)</source>
        <translation>{1}: próbkowanie nie jest możliwe, gdy aktywne jest przeliczanie współrzędnych (cykle 7, 8, 10, 11, 26)</translation>
    </message>
    <message>
        <source>{1}: probing runs with tool axis Z only so far</source>
        <translation>{1}: próbkowanie działa na razie tylko z osią narzędzia Z</translation>
    </message>
    <message>
        <source>cannot write the measuring log {1}: {2}</source>
        <translation>nie można zapisać protokołu pomiaru {1}: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the preset table: {2}</source>
        <translation>cykl próbkowania {1}: nie można zapisać tabeli punktów odniesienia: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1} is not supported yet; the program cannot run past this block</source>
        <translation>cykl próbkowania {1} nie jest jeszcze obsługiwany; program nie może wykonać się poza ten blok</translation>
    </message>
    <message>
        <source>{1} must be an array of three numbers [x, y, z], not {2}</source>
        <translation>{1} musi być listą trzech liczb [x, y, z], nie {2}</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine X; write shift = [x, y, z]</source>
        <translation>Symulacja: o ile rzeczywisty półfabrykat odbiega od zaprogramowanego położenia w X maszyny; napisz shift = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine Y; write shift = [x, y, z]</source>
        <translation>Symulacja: o ile rzeczywisty półfabrykat odbiega od zaprogramowanego położenia w Y maszyny; napisz shift = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine Z; write shift = [x, y, z]</source>
        <translation>Symulacja: o ile rzeczywisty półfabrykat odbiega od zaprogramowanego położenia w Z maszyny; napisz shift = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank is turned about the tool axis, through its programmed origin</source>
        <translation>Symulacja: o ile rzeczywisty półfabrykat jest obrócony wokół osi narzędzia przechodzącej przez jego zaprogramowany punkt zerowy</translation>
    </message>
    <message>
        <source>X of the start point</source>
        <translation>X punktu początkowego</translation>
    </message>
    <message>
        <source>Z of the start point</source>
        <translation>Z punktu początkowego</translation>
    </message>
    <message>
        <source>Program that holds the profile</source>
        <translation>Program zawierający profil</translation>
    </message>
    <message>
        <source>X of the end point</source>
        <translation>X punktu końcowego</translation>
    </message>
    <message>
        <source>Peck reduction factor (tapping: tapping type)</source>
        <translation>Współczynnik zmniejszania kroku wiercenia (gwintowanie: rodzaj gwintowania)</translation>
    </message>
    <message>
        <source>Z of the end point</source>
        <translation>Z punktu końcowego</translation>
    </message>
    <message>
        <source>Label of the first profile block</source>
        <translation>Etykieta pierwszego bloku profilu</translation>
    </message>
    <message>
        <source>Minimum infeed increment</source>
        <translation>Minimalny przyrost dosuwu</translation>
    </message>
    <message>
        <source>Label of the last profile block</source>
        <translation>Etykieta ostatniego bloku profilu</translation>
    </message>
    <message>
        <source>Pass step</source>
        <translation>Krok przejścia</translation>
    </message>
    <message>
        <source>Maximum pass step</source>
        <translation>Maksymalny krok przejścia</translation>
    </message>
    <message>
        <source>Rapid approach to the previous peck</source>
        <translation>Szybki dojazd do poprzedniego kroku</translation>
    </message>
    <message>
        <source>Thread pitch</source>
        <translation>Skok gwintu</translation>
    </message>
    <message>
        <source>Maximum step between plunges</source>
        <translation>Maksymalny odstęp między wcięciami</translation>
    </message>
    <message>
        <source>Stock to remove</source>
        <translation>Naddatek do usunięcia</translation>
    </message>
    <message>
        <source>X distance from the start point to the arc centre</source>
        <translation>Odległość w X od punktu początkowego do środka łuku</translation>
    </message>
    <message>
        <source>Depth from the start point</source>
        <translation>Głębokość od punktu początkowego</translation>
    </message>
    <message>
        <source>Total thread depth</source>
        <translation>Całkowita głębokość gwintu</translation>
    </message>
    <message>
        <source>Feed for plunging into valleys</source>
        <translation>Posuw wcinania w zagłębienia</translation>
    </message>
    <message>
        <source>Z distance from the start point to the arc centre</source>
        <translation>Odległość w Z od punktu początkowego do środka łuku</translation>
    </message>
    <message>
        <source>Measured point of a thread to repass</source>
        <translation>Punkt pomiarowy gwintu do poprawienia</translation>
    </message>
    <message>
        <source>Dwell at the bottom</source>
        <translation>Postój na dnie</translation>
    </message>
    <message>
        <source>Infeed angle</source>
        <translation>Kąt dosuwu</translation>
    </message>
    <message>
        <source>Main machining axis (0: Z, 1: X)</source>
        <translation>Główna oś obróbki (0: Z, 1: X)</translation>
    </message>
    <message>
        <source>Finishing allowance in X</source>
        <translation>Naddatek na wykończenie w X</translation>
    </message>
    <message>
        <source>Minimum peck depth</source>
        <translation>Minimalny krok wiercenia</translation>
    </message>
    <message>
        <source>Finishing pass allowance</source>
        <translation>Naddatek przejścia wykańczającego</translation>
    </message>
    <message>
        <source>Finishing allowance in Z</source>
        <translation>Naddatek na wykończenie w Z</translation>
    </message>
    <message>
        <source>Pitch change per revolution</source>
        <translation>Zmiana skoku na obrót</translation>
    </message>
    <message>
        <source>Rapid retract after each peck</source>
        <translation>Szybkie wycofanie po każdym kroku</translation>
    </message>
    <message>
        <source>Feed of the finishing pass</source>
        <translation>Posuw przejścia wykańczającego</translation>
    </message>
    <message>
        <source>Feed of the final roughing pass</source>
        <translation>Posuw ostatniego przejścia zgrubnego</translation>
    </message>
    <message>
        <source>Safety distance from the thread start</source>
        <translation>Odległość bezpieczna od początku gwintu</translation>
    </message>
    <message>
        <source>Safety distance for the retract</source>
        <translation>Odległość bezpieczna do wycofania</translation>
    </message>
    <message>
        <source>Peck depth (0: tapping)</source>
        <translation>Krok wiercenia (0: gwintowanie)</translation>
    </message>
    <message>
        <source>Depth of the first pass (negative: constant step)</source>
        <translation>Głębokość pierwszego przejścia (ujemna: stały krok)</translation>
    </message>
    <message>
        <source>Thread run-out</source>
        <translation>Wybieg gwintu</translation>
    </message>
    <message>
        <source>Spindle angle at the start or measured point</source>
        <translation>Kąt wrzeciona w punkcie początkowym lub pomiarowym</translation>
    </message>
    <message>
        <source>Number of thread starts</source>
        <translation>Liczba wejść gwintu</translation>
    </message>
    <message>
        <source>One value per field</source>
        <translation>Jedna wartość na pole</translation>
    </message>
    <message>
        <source>Canned
cycles</source>
        <translation>Cykle
stałe</translation>
    </message>
    <message>
        <source>Put the cursor on a canned cycle block (G66-G89) to edit it.</source>
        <translation>Ustaw kursor na bloku cyklu stałego (G66-G89), aby go edytować.</translation>
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
        <translation>Wykonanie blok po bloku</translation>
    </message>
    <message>
        <source>Automatic execution</source>
        <translation>Wykonanie automatyczne</translation>
    </message>
    <message>
        <source>Editing</source>
        <translation>Edycja</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Symulacja</translation>
    </message>
    <message>
        <source>Label numbers of the contour subprograms (up to 12, separated by /)</source>
        <translation>Numery etykiet podprogramów konturu (do 12, oddzielone /)</translation>
    </message>
    <message>
        <source>Inside corner rounding radius</source>
        <translation>Promień zaokrąglenia naroży wewnętrznych</translation>
    </message>
    <message>
        <source>CONTOUR</source>
        <translation>KONTUR</translation>
    </message>
    <message>
        <source>CONTOUR DATA</source>
        <translation>DANE KONTURU</translation>
    </message>
    <message>
        <source>Rough-out tool number (0: the tool in the spindle)</source>
        <translation>Numer narzędzia do przeciągania (0: narzędzie we wrzecionie)</translation>
    </message>
    <message>
        <source>cycle {1} needs a pocket among the contours of cycle 14</source>
        <translation>cykl {1} wymaga kieszeni wśród konturów cyklu 14</translation>
    </message>
    <message>
        <source>cycle {1}: tool {2} ({3}) is not in the tool table</source>
        <translation>cykl {1}: narzędzia {2} ({3}) nie ma w tabeli narzędzi</translation>
    </message>
    <message>
        <source>PILOT DRILLING</source>
        <translation>WIERCENIE WSTEPNE</translation>
    </message>
    <message>
        <source>Coarse roughing tool number (0: none)</source>
        <translation>Numer narzędzia do obróbki zgrubnej wstępnej (0: brak)</translation>
    </message>
    <message>
        <source>Feed rate for reciprocation</source>
        <translation>Posuw ruchu wahadłowego</translation>
    </message>
    <message>
        <source>Feed rate factor in %</source>
        <translation>Współczynnik posuwu w %</translation>
    </message>
    <message>
        <source>Fine roughing strategy (0 along the contour, 1 retract between areas)</source>
        <translation>Strategia obróbki wykańczającej zgrubnej (0 wzdłuż konturu, 1 odsunięcie między obszarami)</translation>
    </message>
    <message>
        <source>cycle {1}: the feed rate for reciprocation Q19 needs the plunge angle ANGLE of the tool</source>
        <translation>cykl {1}: posuw ruchu wahadłowego Q19 wymaga kąta wcięcia ANGLE narzędzia</translation>
    </message>
    <message>
        <source>ROUGH-OUT</source>
        <translation>PRZECIAGANIE</translation>
    </message>
    <message>
        <source>FLOOR FINISHING</source>
        <translation>OBROBKA NA GOTOWO DNA</translation>
    </message>
    <message>
        <source>SIDE FINISHING</source>
        <translation>OBROBKA NA GOTOWO BOKU</translation>
    </message>
    <message>
        <source>cycle {1} needs cycle 20 CONTOUR DATA before it</source>
        <translation>cykl {1} wymaga wcześniej cyklu 20 DANE KONTURU</translation>
    </message>
    <message>
        <source>cycle {1} needs cycle 14 CONTOUR before it</source>
        <translation>cykl {1} wymaga wcześniej cyklu 14 KONTUR</translation>
    </message>
    <message>
        <source>cycle {1}: the islands of cycle 14 cover the whole pocket</source>
        <translation>cykl {1}: wyspy cyklu 14 pokrywają całą kieszeń</translation>
    </message>
    <message>
        <source>Retraction feed rate (0: milling feed)</source>
        <translation>Posuw wycofania (0: posuw frezowania)</translation>
    </message>
    <message>
        <source>cycle 14: a label number from 1 to 65535 expected</source>
        <translation>cykl 14: oczekiwano numeru etykiety od 1 do 65535</translation>
    </message>
    <message>
        <source>cycle 14: label numbers are separated by &apos;/&apos;</source>
        <translation>cykl 14: numery etykiet oddziela się znakiem &apos;/&apos;</translation>
    </message>
    <message>
        <source>cycle 14 lists 1 to 12 label numbers</source>
        <translation>cykl 14 podaje od 1 do 12 numerów etykiet</translation>
    </message>
    <message>
        <source>this block is not allowed in a contour subprogram</source>
        <translation>ten blok jest niedozwolony w podprogramie konturu</translation>
    </message>
    <message>
        <source>a contour subprogram must not move in the tool axis</source>
        <translation>podprogram konturu nie może przemieszczać w osi narzędzia</translation>
    </message>
    <message>
        <source>the first block of a contour subprogram must be a straight line with both working-plane axes</source>
        <translation>pierwszy blok podprogramu konturu musi być prostą z obiema osiami płaszczyzny obróbki</translation>
    </message>
    <message>
        <source>a contour subprogram has more than 16384 blocks</source>
        <translation>podprogram konturu ma więcej niż 16384 bloki</translation>
    </message>
    <message>
        <source>the contour subprogram LBL {1} needs radius compensation RL or RR (pocket or island)</source>
        <translation>podprogram konturu LBL {1} wymaga korekcji promienia RL lub RR (kieszeń lub wyspa)</translation>
    </message>
    <message>
        <source>MILLING DEPTH</source>
        <translation>GLEBOKOSC FREZOW.</translation>
    </message>
    <message>
        <source>TOOL PATH OVERLAP</source>
        <translation>NAKLADANIE TOROW</translation>
    </message>
    <message>
        <source>CLEARANCE HEIGHT</source>
        <translation>BEZPIECZNA WYSOKOSC</translation>
    </message>
    <message>
        <source>ROUNDING RADIUS</source>
        <translation>PROMIEN ZAOKRAGL.</translation>
    </message>
    <message>
        <source>ROTATIONAL DIRECTION</source>
        <translation>KIERUNEK OBROTU</translation>
    </message>
    <message>
        <source>FEED RATE F. ROUGHNG</source>
        <translation>POSUW PRZECIAGANIA</translation>
    </message>
    <message>
        <source>ROUGH-OUT TOOL</source>
        <translation>NARZ. PRZECIAGANIA</translation>
    </message>
    <message>
        <source>COARSE ROUGHING TOOL</source>
        <translation>NARZ. WSTEPNE</translation>
    </message>
    <message>
        <source>FEED RATE FOR RECIP.</source>
        <translation>POSUW RUCHU WAHADL.</translation>
    </message>
    <message>
        <source>FINE ROUGH STRATEGY</source>
        <translation>STRATEGIA DOKONCZ.</translation>
    </message>
    <message>
        <source>after G00 the raw-stock profile needs G01, G02 or G03</source>
        <translation>po G00 profil półfabrykatu wymaga G01, G02 lub G03</translation>
    </message>
    <message>
        <source>An ISO block is either absolute (G90) or incremental (G91): enter all coordinates with I or none</source>
        <translation>Blok ISO jest albo absolutny (G90), albo przyrostowy (G91): wpisz wszystkie współrzędne z I albo żadnej</translation>
    </message>
    <message>
        <source>ISO programs have no FAUTO: enter the feed</source>
        <translation>Programy ISO nie mają FAUTO: wpisz posuw</translation>
    </message>
    <message>
        <source>This cycle has no ISO form</source>
        <translation>Ten cykl nie ma postaci ISO</translation>
    </message>
    <message>
        <source>This block has no ISO form</source>
        <translation>Ten blok nie ma postaci ISO</translation>
    </message>
    <message>
        <source>FK: the relative data refer to block {1}, which is not among the last 64 determined blocks</source>
        <translation>FK: dane przyrostowe odnoszą się do bloku {1}, którego nie ma wśród ostatnich 64 wyznaczonych bloków</translation>
    </message>
    <message>
        <source>FK: polar data need a pole FPOL</source>
        <translation>FK: dane biegunowe wymagają bieguna FPOL</translation>
    </message>
    <message>
        <source>FK: this element has {1} solutions: choose one with FSELECT in the next block</source>
        <translation>FK: ten element ma {1} rozwiązań: wybierz jedno przez FSELECT w następnym bloku</translation>
    </message>
    <message>
        <source>FK: R and LEN must be positive, D must not be negative</source>
        <translation>FK: R i LEN muszą być dodatnie, D nie może być ujemne</translation>
    </message>
    <message>
        <source>FK: CLSD- without a CLSD+ before it</source>
        <translation>FK: CLSD- bez wcześniejszego CLSD+</translation>
    </message>
    <message>
        <source>FSELECT without an FK element with several solutions before it</source>
        <translation>FSELECT bez wcześniejszego elementu FK o kilku rozwiązaniach</translation>
    </message>
    <message>
        <source>FSELECT {1}: the element has {2} solutions</source>
        <translation>FSELECT {1}: element ma {2} rozwiązań</translation>
    </message>
    <message>
        <source>FK: this element is not determined: the FK sequence ends before enough data are given</source>
        <translation>FK: ten element nie jest wyznaczony: sekwencja FK kończy się, zanim podano dość danych</translation>
    </message>
    <message>
        <source>FK: this element is not determined by the blocks that follow it</source>
        <translation>FK: następne bloki nie wyznaczają tego elementu</translation>
    </message>
    <message>
        <source>FK: the data of this block contradict the contour: no solution</source>
        <translation>FK: dane tego bloku są sprzeczne z konturem: brak rozwiązania</translation>
    </message>
    <message>
        <source>FSELECT needs the number of a solution (1 to 99)</source>
        <translation>FSELECT wymaga numeru rozwiązania (1 do 99)</translation>
    </message>
    <message>
        <source>unexpected text</source>
        <translation>nieoczekiwany tekst</translation>
    </message>
    <message>
        <source>FPOL takes X and Y once each</source>
        <translation>FPOL przyjmuje X i Y po jednym razie</translation>
    </message>
    <message>
        <source>FPOL needs X and Y</source>
        <translation>FPOL wymaga X i Y</translation>
    </message>
    <message>
        <source>this FK datum is programmed twice</source>
        <translation>ta dana FK jest zaprogramowana dwa razy</translation>
    </message>
    <message>
        <source>CLSD+ or CLSD- expected</source>
        <translation>oczekiwano CLSD+ lub CLSD-</translation>
    </message>
    <message>
        <source>the block number relative data refer to expected</source>
        <translation>oczekiwano numeru bloku, do którego odnoszą się dane przyrostowe</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in an FK block</source>
        <translation>nieoczekiwane &apos;{1}&apos; w bloku FK</translation>
    </message>
    <message>
        <source>P{1}X and P{1}Y are given together</source>
        <translation>P{1}X i P{1}Y podaje się razem</translation>
    </message>
    <message>
        <source>{1} needs an incremental value {2} in the same block</source>
        <translation>{1} wymaga wartości przyrostowej {2} w tym samym bloku</translation>
    </message>
    <message>
        <source>1st touch point, nominal surface in the tool axis</source>
        <translation>1. punkt próbkowania, powierzchnia nominalna w osi narzędzia</translation>
    </message>
    <message>
        <source>2nd touch point, nominal surface in the tool axis</source>
        <translation>2. punkt próbkowania, powierzchnia nominalna w osi narzędzia</translation>
    </message>
    <message>
        <source>3rd touch point, nominal surface in the tool axis</source>
        <translation>3. punkt próbkowania, powierzchnia nominalna w osi narzędzia</translation>
    </message>
    <message>
        <source>cycle {1}: the three touch points lie on one line</source>
        <translation>cykl {1}: trzy punkty próbkowania leżą na jednej prostej</translation>
    </message>
    <message>
        <source>MEASURE BOLT HOLE CIRC</source>
        <translation>POMIAR OKREGU ODWIERTOW</translation>
    </message>
    <message>
        <source>MEASURE PLANE</source>
        <translation>POMIAR PLASZCZYZNY</translation>
    </message>
    <message>
        <source>1st centre, main axis</source>
        <translation>1. środek, oś główna</translation>
    </message>
    <message>
        <source>1st centre, secondary axis</source>
        <translation>1. środek, oś pomocnicza</translation>
    </message>
    <message>
        <source>2nd centre, main axis</source>
        <translation>2. środek, oś główna</translation>
    </message>
    <message>
        <source>2nd centre, secondary axis</source>
        <translation>2. środek, oś pomocnicza</translation>
    </message>
    <message>
        <source>Compensation: 0 basic rotation, 1 rotary table</source>
        <translation>Kompensacja: 0 obrót bazowy, 1 stół obrotowy</translation>
    </message>
    <message>
        <source>Set the rotary axis display to 0 after alignment: 0 no, 1 yes</source>
        <translation>Ustawić wskazanie osi obrotowej na 0 po wyrównaniu: 0 nie, 1 tak</translation>
    </message>
    <message>
        <source>Diameter of stud 1 (rather too large)</source>
        <translation>Średnica czopu 1 (raczej za duża)</translation>
    </message>
    <message>
        <source>Diameter of stud 2 (rather too large)</source>
        <translation>Średnica czopu 2 (raczej za duża)</translation>
    </message>
    <message>
        <source>Measuring height at stud 2: ball centre in the tool axis</source>
        <translation>Wysokość pomiaru przy czopie 2: środek kulki w osi narzędzia</translation>
    </message>
    <message>
        <source>3rd centre, main axis</source>
        <translation>3. środek, oś główna</translation>
    </message>
    <message>
        <source>3rd centre, secondary axis</source>
        <translation>3. środek, oś pomocnicza</translation>
    </message>
    <message>
        <source>4th centre, main axis</source>
        <translation>4. środek, oś główna</translation>
    </message>
    <message>
        <source>4th centre, secondary axis</source>
        <translation>4. środek, oś pomocnicza</translation>
    </message>
    <message>
        <source>ROT 2 HOLES</source>
        <translation>ROT 2 ODWIERTY</translation>
    </message>
    <message>
        <source>ROT 2 STUDS</source>
        <translation>ROT 2 CZOPY</translation>
    </message>
    <message>
        <source>DATUM FROM 4 HOLES</source>
        <translation>PKT. ODN. 4 ODWIERTY</translation>
    </message>
    <message>
        <source>Width of the slot or ridge, whatever its orientation</source>
        <translation>Szerokość rowka lub mostka, niezależnie od położenia</translation>
    </message>
    <message>
        <source>New datum in the measuring axis for the centre</source>
        <translation>Nowy punkt odniesienia w osi pomiaru dla środka</translation>
    </message>
    <message>
        <source>SLOT CENTER REF PT</source>
        <translation>PKT ODN. SRODEK ROWKA</translation>
    </message>
    <message>
        <source>RIDGE CENTER REF PT</source>
        <translation>PKT ODN. SRODEK MOSTKA</translation>
    </message>
    <message>
        <source>Tool measurement: 0 write L/R, 1 compare and write DL/DR, 2 compare</source>
        <translation>Pomiar narzędzia: 0 zapisać L/R, 1 porównać i zapisać DL/DR, 2 porównać</translation>
    </message>
    <message>
        <source>Probe each tooth: 0 no, 1 yes</source>
        <translation>Próbkować każde ostrze: 0 nie, 1 tak</translation>
    </message>
    <message>
        <source>CALIBRATE TT</source>
        <translation>TT KALIBROWAC</translation>
    </message>
    <message>
        <source>TOOL LENGTH</source>
        <translation>DLUGOSC NARZEDZIA</translation>
    </message>
    <message>
        <source>TOOL RADIUS</source>
        <translation>PROMIEN NARZEDZIA</translation>
    </message>
    <message>
        <source>MEASURE TOOL</source>
        <translation>POMIAR NARZEDZIA</translation>
    </message>
    <message>
        <source>TCH PROBE {1}.{2} without TCH PROBE {1}.0 before it</source>
        <translation>TCH PROBE {1}.{2} bez poprzedzającego TCH PROBE {1}.0</translation>
    </message>
    <message>
        <source>{1}.{2}: a number after &apos;:&apos; expected</source>
        <translation>{1}.{2}: po &apos;:&apos; oczekiwana liczba</translation>
    </message>
    <message>
        <source>{1}: sub-blocks .1, .2 and .3 are needed</source>
        <translation>{1}: potrzebne są bloki częściowe .1, .2 i .3</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the machine has no tool touch probe ([simulation.tool_probe] enabled = true)</source>
        <translation>cykl sondy {1}: maszyna nie ma sondy narzędziowej ([simulation.tool_probe] enabled = true)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: tool measurement is not possible while mirroring or scaling is active (cycles 8, 11, 26)</source>
        <translation>cykl sondy {1}: pomiar narzędzia nie jest możliwy przy aktywnym odbiciu lustrzanym lub skalowaniu (cykle 8, 11, 26)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: probing runs with tool axis Z only so far</source>
        <translation>cykl sondy {1}: próbkowanie działa na razie tylko z osią narzędzia Z</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: call the tool to be measured from the tool table TOOL.T with TOOL CALL first</source>
        <translation>cykl sondy {1}: najpierw wywołać mierzone narzędzie z tabeli narzędzi TOOL.T przez TOOL CALL</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the tool table: {2}</source>
        <translation>cykl sondy {1}: nie można zapisać tabeli narzędzi: {2}</translation>
    </message>
    <message>
        <source>{1} must be tables [[{1}]] with tool, length and radius</source>
        <translation>{1} muszą być tabelami [[{1}]] z tool, length i radius</translation>
    </message>
    <message>
        <source>{1} = {2} is out of range: a tool number 0 ... 32767, lengths within +-10 mm</source>
        <translation>{1} = {2} poza zakresem: numer narzędzia 0 ... 32767, długości w granicach +-10 mm</translation>
    </message>
    <message>
        <source>{1} needs a tool number</source>
        <translation>{1} wymaga numeru narzędzia</translation>
    </message>
    <message>
        <source>{1}: tool {2} is given twice</source>
        <translation>{1}: narzędzie {2} podano dwukrotnie</translation>
    </message>
    <message>
        <source>Simulation: the machine has a tool touch probe (TT) for the tool measuring cycles 30-33 and 480-483</source>
        <translation>Symulacja: maszyna ma sondę narzędziową (TT) dla cykli pomiaru narzędzi 30-33 i 480-483</translation>
    </message>
    <message>
        <source>TT: machine X of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: maszynowe X środka powierzchni pomiarowej; zapisać centre = [x, y, z]</translation>
    </message>
    <message>
        <source>TT: machine Y of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: maszynowe Y środka powierzchni pomiarowej; zapisać centre = [x, y, z]</translation>
    </message>
    <message>
        <source>TT: machine Z of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: maszynowe Z środka powierzchni pomiarowej; zapisać centre = [x, y, z]</translation>
    </message>
    <message>
        <source>TT: diameter of the disc stylus (side of a cube stylus)</source>
        <translation>TT: średnica trzpienia tarczowego (bok trzpienia sześciennego)</translation>
    </message>
    <message>
        <source>TT: stylus shape, a disc or a cube</source>
        <translation>TT: kształt trzpienia, tarcza lub sześcian</translation>
    </message>
    <message>
        <source>TT: how far below the top of the stylus the end face of the tool sits when its radius is measured</source>
        <translation>TT: jak głęboko pod górną krawędzią trzpienia znajduje się czoło narzędzia przy pomiarze promienia</translation>
    </message>
    <message>
        <source>TT: safety zone above the stylus, and how far before the stylus each touch starts</source>
        <translation>TT: strefa bezpieczeństwa nad trzpieniem i odległość przed trzpieniem, z której zaczyna się każde próbkowanie</translation>
    </message>
    <message>
        <source>TT: highest cutting-edge speed of a rotating tool; sets the measuring speed</source>
        <translation>TT: największa prędkość ostrza obracającego się narzędzia; określa prędkość pomiaru</translation>
    </message>
    <message>
        <source>TT: measuring error allowed with a rotating tool; probing feed = tolerance x speed</source>
        <translation>TT: dopuszczalny błąd pomiaru przy obracającym się narzędziu; posuw próbkowania = tolerancja x prędkość</translation>
    </message>
    <message>
        <source>TT: probing feed with a stationary spindle</source>
        <translation>TT: posuw próbkowania przy zatrzymanym wrzecionie</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the tool to monitor (Q330 = {2}) is not in the tool table</source>
        <translation>cykl sondy {1}: nadzorowanego narzędzia (Q330 = {2}) nie ma w tabeli narzędzi</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: tool {2} is broken (deviation {3} mm beyond RBREAK); it is locked</source>
        <translation>cykl sondy {1}: narzędzie {2} jest złamane (odchyłka {3} mm ponad RBREAK); zostało zablokowane</translation>
    </message>
    <message>
        <source>Climb or up-cut (+1 climb, -1 up-cut, 0 alternating)</source>
        <translation>Frezowanie współbieżne lub przeciwbieżne (+1 współbieżne, -1 przeciwbieżne, 0 na przemian)</translation>
    </message>
    <message>
        <source>Accepted residual material</source>
        <translation>Akceptowany materiał resztkowy</translation>
    </message>
    <message>
        <source>Maximum connection distance</source>
        <translation>Maksymalna odległość połączenia</translation>
    </message>
    <message>
        <source>Path extension</source>
        <translation>Wydłużenie toru</translation>
    </message>
    <message>
        <source>cycle {1}: with cycle 270 the contour subprogram must be programmed without RL/RR (Q391 gives the side)</source>
        <translation>cykl {1}: z cyklem 270 podprogram konturu musi być zaprogramowany bez RL/RR (Q391 określa stronę)</translation>
    </message>
    <message>
        <source>CONTOUR TRAIN</source>
        <translation>LINIA KONTURU</translation>
    </message>
    <message>
        <source>Type of approach/departure (1 arc, 2 tangent line, 3 perpendicular)</source>
        <translation>Rodzaj dosunięcia/odsunięcia (1 łuk, 2 prosta styczna, 3 prostopadle)</translation>
    </message>
    <message>
        <source>Radius compensation (0 R0, 1 RL, 2 RR)</source>
        <translation>Korekcja promienia (0 R0, 1 RL, 2 RR)</translation>
    </message>
    <message>
        <source>Radius of the approach/departure arc</source>
        <translation>Promień łuku dosunięcia/odsunięcia</translation>
    </message>
    <message>
        <source>Centre angle of the approach/departure arc</source>
        <translation>Kąt środkowy łuku dosunięcia/odsunięcia</translation>
    </message>
    <message>
        <source>Distance of the auxiliary point</source>
        <translation>Odległość punktu pomocniczego</translation>
    </message>
    <message>
        <source>CONTOUR TRAIN DATA</source>
        <translation>DANE LINII KONTURU</translation>
    </message>
    <message>
        <source>cycle {1}: cycle 14 must list exactly one contour subprogram (the slot&apos;s centre line)</source>
        <translation>cykl {1}: cykl 14 musi zawierać dokładnie jeden podprogram konturu (linię środkową rowka)</translation>
    </message>
    <message>
        <source>cycle {1}: the start point of a closed slot must not lie on a corner of the contour</source>
        <translation>cykl {1}: punkt startu zamkniętego rowka nie może leżeć na narożu konturu</translation>
    </message>
    <message>
        <source>cycle {1}: the plunging depth Q202 must be greater than 0</source>
        <translation>cykl {1}: głębokość dosuwu Q202 musi być większa od 0</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width less the side allowances is more than twice the tool diameter</source>
        <translation>cykl {1}: szerokość rowka pomniejszona o naddatki boczne jest większa niż dwukrotna średnica narzędzia</translation>
    </message>
    <message>
        <source>cycle {1}: the infeed per revolution Q436 must be greater than 0</source>
        <translation>cykl {1}: dosuw na obrót Q436 musi być większy od 0</translation>
    </message>
    <message>
        <source>Infeed per revolution (trochoidal loop)</source>
        <translation>Dosuw na obrót (pętla trochoidalna)</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 no function, 2 reciprocating)</source>
        <translation>Strategia wcięcia (0 pionowo, 1 bez funkcji, 2 ruchem wahadłowym)</translation>
    </message>
    <message>
        <source>TROCHOIDAL SLOT</source>
        <translation>ROWEK KONTURU TROCHOIDALNIE</translation>
    </message>
    <message>
        <source>Strategy (0 meander outside, 1 meander on the edge, 2 line by line, 3 line by line to the edge, 4 spiral)</source>
        <translation>Strategia (0 meander na zewnątrz, 1 meander na krawędzi, 2 wierszami, 3 wierszami do krawędzi, 4 spirala)</translation>
    </message>
    <message>
        <source>Milling direction (1 main axis, 2 secondary axis)</source>
        <translation>Kierunek frezowania (1 oś główna, 2 oś pomocnicza)</translation>
    </message>
    <message>
        <source>1st limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>1. ograniczenie (0 brak, -1/+1 oś główna, -2/+2 oś pomocnicza)</translation>
    </message>
    <message>
        <source>2nd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>2. ograniczenie (0 brak, -1/+1 oś główna, -2/+2 oś pomocnicza)</translation>
    </message>
    <message>
        <source>3rd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>3. ograniczenie (0 brak, -1/+1 oś główna, -2/+2 oś pomocnicza)</translation>
    </message>
    <message>
        <source>Corner radius</source>
        <translation>Promień naroża</translation>
    </message>
    <message>
        <source>cycle {1}: limits Q347-Q349 are not possible with the spiral strategy Q389 = 4</source>
        <translation>cykl {1}: ograniczenia Q347-Q349 nie są możliwe ze strategią spiralną Q389 = 4</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is too large for the face between its walls</source>
        <translation>cykl {1}: narzędzie jest za duże dla powierzchni między jej ściankami</translation>
    </message>
    <message>
        <source>1ST LIMIT</source>
        <translation>1. OGRANICZENIE</translation>
    </message>
    <message>
        <source>2ND LIMIT</source>
        <translation>2. OGRANICZENIE</translation>
    </message>
    <message>
        <source>3RD LIMIT</source>
        <translation>3. OGRANICZENIE</translation>
    </message>
    <message>
        <source>MILLING DIRECTION</source>
        <translation>KIERUNEK FREZOWANIA</translation>
    </message>
    <message>
        <source>TYPE OF APPROACH</source>
        <translation>RODZAJ DOSUNIĘCIA</translation>
    </message>
    <message>
        <source>RADIUS COMPENSATION</source>
        <translation>KOREKCJA PROMIENIA</translation>
    </message>
    <message>
        <source>RADIUS</source>
        <translation>PROMIEŃ</translation>
    </message>
    <message>
        <source>CENTER ANGLE</source>
        <translation>KĄT ŚRODKOWY</translation>
    </message>
    <message>
        <source>DISTANCE</source>
        <translation>ODSTĘP</translation>
    </message>
    <message>
        <source>INFEED PER REV.</source>
        <translation>DOSUW NA OBRÓT</translation>
    </message>
    <message>
        <source>RESIDUAL MATERIAL</source>
        <translation>MATERIAŁ RESZTKOWY</translation>
    </message>
    <message>
        <source>CONNECTION DISTANCE</source>
        <translation>ODLEGŁOŚĆ POŁĄCZENIA</translation>
    </message>
    <message>
        <source>PATH EXTENSION</source>
        <translation>WYDŁUŻENIE TORU</translation>
    </message>
    <message>
        <source>MILLING STRATEGY</source>
        <translation>STRATEGIA FREZOWANIA</translation>
    </message>
    <message>
        <source>cycle {1}: cycle 14 must list exactly one contour subprogram</source>
        <translation>cykl {1}: cykl 14 musi zawierać dokładnie jeden podprogram konturu</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is below the clearance height Q7 at the call</source>
        <translation>cykl {1}: narzędzie znajduje się przy wywołaniu poniżej wysokości bezpiecznej Q7</translation>
    </message>
    <message>
        <source>3-D CONTOUR TRAIN</source>
        <translation>LINIA KONTURU 3D</translation>
    </message>
    <message>
        <source>the first block of a 3-D contour subprogram must give the tool axis too</source>
        <translation>pierwszy blok podprogramu konturu 3D musi podawać także oś narzędzia</translation>
    </message>
    <message>
        <source>PLANE: SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL or RESET expected</source>
        <translation>PLANE: oczekiwano SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL lub RESET</translation>
    </message>
    <message>
        <source>PLANE {1}: {2} expected</source>
        <translation>PLANE {1}: oczekiwano {2}</translation>
    </message>
    <message>
        <source>PLANE RELATIV: SPA, SPB or SPC expected</source>
        <translation>PLANE RELATIV: oczekiwano SPA, SPB lub SPC</translation>
    </message>
    <message>
        <source>PLANE AXIAL: an angle of A, B or C expected</source>
        <translation>PLANE AXIAL: oczekiwano kąta A, B lub C</translation>
    </message>
    <message>
        <source>SEQ+ or SEQ- expected</source>
        <translation>oczekiwano SEQ+ lub SEQ-</translation>
    </message>
    <message>
        <source>ROT expected</source>
        <translation>oczekiwano ROT</translation>
    </message>
    <message>
        <source>PLANE: unexpected &apos;{1}&apos;</source>
        <translation>PLANE: nieoczekiwane &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>PLANE: MOVE, TURN or STAY expected</source>
        <translation>PLANE: oczekiwano MOVE, TURN lub STAY</translation>
    </message>
    <message>
        <source>PLANE: the points or vectors do not define a plane</source>
        <translation>PLANE: punkty lub wektory nie określają płaszczyzny</translation>
    </message>
    <message>
        <source>{1} needs rotary axes: this machine has none</source>
        <translation>{1} wymaga osi obrotowych: ta maszyna ich nie ma</translation>
    </message>
    <message>
        <source>{1} needs the rotary tables described in the machine file ([kinematics], docs/machine-config.md)</source>
        <translation>{1} wymaga stołów obrotowych opisanych w pliku maszyny ([kinematics], docs/machine-config.md)</translation>
    </message>
    <message>
        <source>the rotary axes of this machine cannot turn the tool perpendicular to this plane</source>
        <translation>osie obrotowe tej maszyny nie mogą ustawić narzędzia prostopadle do tej płaszczyzny</translation>
    </message>
    <message>
        <source>no solution for the rotary axes lies within their soft limits (and the SEQ chosen): {1}</source>
        <translation>żadne rozwiązanie dla osi obrotowych nie leży w ich programowych wyłącznikach krańcowych (i wybranym SEQ): {1}</translation>
    </message>
    <message>
        <source>PLANE with radius compensation RL/RR: program R0 first</source>
        <translation>PLANE z korekcją promienia RL/RR: najpierw zaprogramuj R0</translation>
    </message>
    <message>
        <source>cycle 19: unexpected &apos;{1}&apos;</source>
        <translation>cykl 19: nieoczekiwane &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>the move would take axis {1} to {2} deg (machine coordinates), beyond its soft limit {3}</source>
        <translation>ruch doprowadziłby oś {1} do {2} stopni (współrzędne maszynowe), poza jej programowy wyłącznik krańcowy {3}</translation>
    </message>
    <message>
        <source>Machine X where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>X maszyny, gdzie spotykają się osie obrotowe; zapisz pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Machine Y where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>Y maszyny, gdzie spotykają się osie obrotowe; zapisz pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Machine Z where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>Z maszyny, gdzie spotykają się osie obrotowe; zapisz pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Rotary: turns without end; no soft limits, M126 takes the short way</source>
        <translation>Obrotowa: obraca się bez końca; bez programowych wyłączników krańcowych, M126 wybiera krótszą drogę</translation>
    </message>
    <message>
        <source>{1} = true is only allowed on a rotary axis</source>
        <translation>{1} = true jest dozwolone tylko dla osi obrotowej</translation>
    </message>
    <message>
        <source>{1} = &quot;{2}&quot; is not an enabled rotary axis of this machine</source>
        <translation>{1} = &quot;{2}&quot; nie jest włączoną osią obrotową tej maszyny</translation>
    </message>
    <message>
        <source>kinematics.secondary must be another axis than kinematics.primary</source>
        <translation>kinematics.secondary musi być inną osią niż kinematics.primary</translation>
    </message>
    <message>
        <source>P{1} expected after G18</source>
        <translation>oczekiwano P{1} po G18</translation>
    </message>
    <message>
        <source>Show
solution</source>
        <translation>Pokaż
rozwiązanie</translation>
    </message>
    <message>
        <source>Select
solution</source>
        <translation>Wybierz
rozwiązanie</translation>
    </message>
    <message>
        <source>cycle {1}: the contour formula leaves no area to machine</source>
        <translation>cykl {1}: formuła konturu nie pozostawia powierzchni do obróbki</translation>
    </message>
    <message>
        <source>parentheses nested too deep</source>
        <translation>nawiasy zagnieżdżone zbyt głęboko</translation>
    </message>
    <message>
        <source>a contour descriptor QC1 ... QC65535 or &apos;(&apos; expected</source>
        <translation>oczekiwano deskryptora konturu QC1 ... QC65535 lub &apos;(&apos;</translation>
    </message>
    <message>
        <source>program name in quotes expected</source>
        <translation>oczekiwano nazwy programu w cudzysłowie</translation>
    </message>
    <message>
        <source>DEPTH value expected</source>
        <translation>oczekiwano wartości DEPTH</translation>
    </message>
    <message>
        <source>unexpected text &apos;{1}&apos;</source>
        <translation>nieoczekiwany tekst &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>a contour descriptor QC1 ... QC65535 expected</source>
        <translation>oczekiwano deskryptora konturu QC1 ... QC65535</translation>
    </message>
    <message>
        <source>pocket P1 ... P9 or island I1 ... I9 expected</source>
        <translation>oczekiwano kieszeni P1 ... P9 lub wysepki I1 ... I9</translation>
    </message>
    <message>
        <source>CONTOUR DEF combines at most 9 subcontours</source>
        <translation>CONTOUR DEF łączy najwyżej 9 konturów częściowych</translation>
    </message>
    <message>
        <source>the first subcontour of CONTOUR DEF must be a pocket (P)</source>
        <translation>pierwszy kontur częściowy CONTOUR DEF musi być kieszenią (P)</translation>
    </message>
    <message>
        <source>CONTOUR DEF needs a pocket P1 = &quot;program&quot;</source>
        <translation>CONTOUR DEF wymaga kieszeni P1 = &quot;program&quot;</translation>
    </message>
    <message>
        <source>a contour formula combines at most 128 contours</source>
        <translation>formuła konturu łączy najwyżej 128 konturów</translation>
    </message>
    <message>
        <source>QC{1} is not declared (DECLARE CONTOUR)</source>
        <translation>QC{1} nie jest zadeklarowany (DECLARE CONTOUR)</translation>
    </message>
    <message>
        <source>the contour formula is too long</source>
        <translation>formuła konturu jest zbyt długa</translation>
    </message>
    <message>
        <source>cannot read the contour program {1}: {2}</source>
        <translation>nie można odczytać programu konturu {1}: {2}</translation>
    </message>
    <message>
        <source>the contour program {1} has errors</source>
        <translation>program konturu {1} zawiera błędy</translation>
    </message>
    <message>
        <source>this block is not allowed in a contour-definition program</source>
        <translation>ten blok jest niedozwolony w programie definicji konturu</translation>
    </message>
    <message>
        <source>every contour needs a DEPTH when one has it (DEPTH0: the depth of cycle 20)</source>
        <translation>każdy kontur wymaga DEPTH, gdy jeden go ma (DEPTH0: głębokość z cyklu 20)</translation>
    </message>
    <message>
        <source>the contour program {1} has no formula QC.. = ...</source>
        <translation>program konturu {1} nie ma formuły QC.. = ...</translation>
    </message>
    <message>
        <source>the contour program {1} has no contour</source>
        <translation>program konturu {1} nie zawiera konturu</translation>
    </message>
    <message>
        <source>the contour of {1} lies beyond 1,000,000 mm from the origin</source>
        <translation>kontur {1} leży dalej niż 1 000 000 mm od punktu zerowego</translation>
    </message>
    <message>
        <source>the contour of {1} encloses no area</source>
        <translation>kontur {1} nie obejmuje żadnej powierzchni</translation>
    </message>
    <message>
        <source>the contour of {1} intersects itself</source>
        <translation>kontur {1} przecina sam siebie</translation>
    </message>
    <message>
        <source>no input is asked for</source>
        <translation>nie jest wymagane żadne wejście</translation>
    </message>
    <message>
        <source>a customisation program runs in the user channel: it has no ISO blocks (no motion, no M, S, T)</source>
        <translation>program personalizacji działa w kanale użytkownika: nie ma bloków ISO (bez ruchu, bez M, S, T)</translation>
    </message>
    <message>
        <source>{1} is a screen customisation instruction: it runs only in a user customisation program (the user screen)</source>
        <translation>{1} jest instrukcją personalizacji ekranu: działa tylko w programie personalizacji użytkownika (ekran użytkownika)</translation>
    </message>
    <message>
        <source>screen customisation instructions run only in a user customisation program (the user screen)</source>
        <translation>instrukcje personalizacji ekranu działają tylko w programie personalizacji użytkownika (ekran użytkownika)</translation>
    </message>
    <message>
        <source>data window {1} is not defined (ODW)</source>
        <translation>okno danych {1} nie jest zdefiniowane (ODW)</translation>
    </message>
    <message>
        <source>WKEY: keys come from the PLC or DNC (KEYSRC), which this control does not have</source>
        <translation>WKEY: klawisze pochodzą z PLC lub DNC (KEYSRC), których to sterowanie nie ma</translation>
    </message>
    <message>
        <source>WBUF runs only in the customisation program of the edit mode (USEREDIT)</source>
        <translation>WBUF działa tylko w programie personalizacji trybu edycji (USEREDIT)</translation>
    </message>
    <message>
        <source>{1}: inputs are IB0-IB25</source>
        <translation>{1}: wejścia to IB0-IB25</translation>
    </message>
    <message>
        <source>customisation instructions take global parameters, not the local P{1}</source>
        <translation>instrukcje personalizacji przyjmują parametry globalne, nie lokalny P{1}</translation>
    </message>
    <message>
        <source>input format [-]i.d expected (i integer digits 0-6, d decimals 0-5)</source>
        <translation>oczekiwano formatu wejścia [-]i.d (i cyfr całkowitych 0-6, d miejsc dziesiętnych 0-5)</translation>
    </message>
    <message>
        <source>a softkey text has at most 20 characters</source>
        <translation>tekst softkeya ma najwyżej 20 znaków</translation>
    </message>
    <message>
        <source>only positive values are accepted here</source>
        <translation>tutaj dopuszczalne są tylko wartości dodatnie</translation>
    </message>
    <message>
        <source>a number is expected</source>
        <translation>oczekiwana jest liczba</translation>
    </message>
    <message>
        <source>the number does not fit the input format</source>
        <translation>liczba nie pasuje do formatu wejścia</translation>
    </message>
    <message>
        <source>Exact radius of the calibration ring or stud</source>
        <translation>Dokładny promień pierścienia lub czopu kalibracyjnego</translation>
    </message>
    <message>
        <source>Number of touch points on the diameter (0: 4)</source>
        <translation>Liczba punktów próbkowania na średnicy (0: 4)</translation>
    </message>
    <message>
        <source>Reference angle: main axis to touch point 1</source>
        <translation>Kąt odniesienia: oś główna do punktu próbkowania 1</translation>
    </message>
    <message>
        <source>Datum for the length: height of the ring&apos;s top face</source>
        <translation>Punkt odniesienia dla długości: wysokość górnej powierzchni pierścienia</translation>
    </message>
    <message>
        <source>CALIBRATE TS LENGTH</source>
        <translation>KALIBROWANIE DŁUGOŚCI TS</translation>
    </message>
    <message>
        <source>CALIBRATE TS IN RING</source>
        <translation>KALIBROWANIE TS W PIERŚCIENIU</translation>
    </message>
    <message>
        <source>CALIBRATE TS ON STUD</source>
        <translation>KALIBROWANIE TS NA CZOPIE</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main axis, 2 secondary axis, 3 touch probe axis</source>
        <translation>Oś pomiarowa: 1 oś główna, 2 oś pomocnicza, 3 oś sondy</translation>
    </message>
    <message>
        <source>Axis for the compensation: 0 automatic, 4 A, 5 B, 6 C</source>
        <translation>Oś kompensacji: 0 automatycznie, 4 A, 5 B, 6 C</translation>
    </message>
    <message>
        <source>Set to zero after alignment: 0 no, 1 yes</source>
        <translation>Zerowanie po wyrównaniu: 0 nie, 1 tak</translation>
    </message>
    <message>
        <source>Reference angle the probed line is aligned to</source>
        <translation>Kąt odniesienia, do którego wyrównywana jest próbkowana prosta</translation>
    </message>
    <message>
        <source>cycle {1}: Q312 must be 0, 4, 5 or 6</source>
        <translation>cykl {1}: Q312 musi wynosić 0, 4, 5 lub 6</translation>
    </message>
    <message>
        <source>cycle {1}: the machine has no rotary table axis {2} to compensate the misalignment</source>
        <translation>cykl {1}: maszyna nie ma osi stołu obrotowego {2} do kompensacji ukośnego położenia</translation>
    </message>
    <message>
        <source>cycle {1}: the rotary axis {2} cannot compensate a misalignment about the axis of {3}</source>
        <translation>cykl {1}: oś obrotowa {2} nie może skompensować ukośnego położenia wokół osi {3}</translation>
    </message>
    <message>
        <source>Preset rotation angle: the basic rotation to set</source>
        <translation>Kąt obrotu: obrót podstawowy do ustawienia</translation>
    </message>
    <message>
        <source>Number in table: -1 the active preset, 0 preset 0 and active</source>
        <translation>Numer w tabeli: -1 aktywny punkt bazowy, 0 punkt bazowy 0 i aktywny</translation>
    </message>
    <message>
        <source>Hole centre, main axis</source>
        <translation>Środek otworu, oś główna</translation>
    </message>
    <message>
        <source>Hole centre, secondary axis: 0 aligns the hole to +Y</source>
        <translation>Środek otworu, oś pomocnicza: 0 wyrównuje otwór do +Y</translation>
    </message>
    <message>
        <source>Nominal diameter (enter it on the small side)</source>
        <translation>Średnica nominalna (podać raczej mniejszą)</translation>
    </message>
    <message>
        <source>Set to zero after alignment: 0 the C display, n add to datum row n</source>
        <translation>Zerowanie po wyrównaniu: 0 wskazanie C, n dodać do wiersza n punktów zerowych</translation>
    </message>
    <message>
        <source>BASIC ROTATION COMPENSATED VIA ROTARY AXIS</source>
        <translation>OBRÓT PODSTAWOWY KOMPENSOWANY OSIĄ OBROTOWĄ</translation>
    </message>
    <message>
        <source>SET BASIC ROTATION</source>
        <translation>USTAWIENIE OBROTU PODSTAWOWEGO</translation>
    </message>
    <message>
        <source>ROT IN C AXIS</source>
        <translation>OBRÓT PRZEZ OŚ C</translation>
    </message>
    <message>
        <source>Positioning feed rate of the probe (FMAX: rapid traverse)</source>
        <translation>Posuw pozycjonowania sondy (FMAX: bieg szybki)</translation>
    </message>
    <message>
        <source>Pre-position at machine rapid: 0 no (Q396), 1 yes</source>
        <translation>Pozycjonowanie wstępne biegiem szybkim maszyny: 0 nie (Q396), 1 tak</translation>
    </message>
    <message>
        <source>Angle tracking: 0 no, 1 orient the probe before each touch</source>
        <translation>Nadążanie kątowe: 0 nie, 1 orientować sondę przed każdym próbkowaniem</translation>
    </message>
    <message>
        <source>Automatic interruption: 0 never, 1 when a cycle shows its log</source>
        <translation>Automatyczne przerwanie: 0 nigdy, 1 gdy cykl pokazuje protokół</translation>
    </message>
    <message>
        <source>Nominal point, main axis</source>
        <translation>Punkt nominalny, oś główna</translation>
    </message>
    <message>
        <source>Nominal point, secondary axis</source>
        <translation>Punkt nominalny, oś pomocnicza</translation>
    </message>
    <message>
        <source>Nominal point, tool axis</source>
        <translation>Punkt nominalny, oś narzędzia</translation>
    </message>
    <message>
        <source>Surface normal, main axis component</source>
        <translation>Normalna do powierzchni, składowa osi głównej</translation>
    </message>
    <message>
        <source>Surface normal, secondary axis component</source>
        <translation>Normalna do powierzchni, składowa osi pomocniczej</translation>
    </message>
    <message>
        <source>Surface normal, tool axis component</source>
        <translation>Normalna do powierzchni, składowa osi narzędzia</translation>
    </message>
    <message>
        <source>Tolerance along the normal, e.g. &quot;0.4-0.1&quot;</source>
        <translation>Tolerancja wzdłuż normalnej, np. &quot;0.4-0.1&quot;</translation>
    </message>
    <message>
        <source>Tolerance error: 0 nothing, 1 stop, 2 stop on undersize only</source>
        <translation>Błąd tolerancji: 0 nic, 1 stop, 2 stop tylko przy niedowymiarze</translation>
    </message>
    <message>
        <source>cycle {1}: the surface normal Q581..Q583 is zero</source>
        <translation>cykl {1}: normalna do powierzchni Q581..Q583 jest zerowa</translation>
    </message>
    <message>
        <source>FAST PROBING</source>
        <translation>SZYBKIE PRÓBKOWANIE</translation>
    </message>
    <message>
        <source>PROBING IN 3-D</source>
        <translation>PRÓBKOWANIE 3D</translation>
    </message>
    <message>
        <source>Stop before running: 0 stop to position the tool, 1 no stop</source>
        <translation>Stop przed wykonaniem: 0 stop do pozycjonowania narzędzia, 1 bez stopu</translation>
    </message>
    <message>
        <source>CALIBRATE IR TT</source>
        <translation>KALIBROWANIE TT IR</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: Q303 = 0 writes the active datum table: select one with SEL TABLE first</source>
        <translation>cykl sondy {1}: Q303 = 0 zapisuje aktywną tabelę punktów zerowych: najpierw wybrać ją przez SEL TABLE</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the datum table: {2}</source>
        <translation>cykl sondy {1}: nie można zapisać tabeli punktów zerowych: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: calibration writes the probe&apos;s row of the tool table TOOL.T: call the probe from it</source>
        <translation>cykl sondy {1}: kalibracja zapisuje wiersz sondy w tabeli narzędzi TOOL.T: wywołać sondę z tej tabeli</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the TT calibration: {2}</source>
        <translation>cykl sondy {1}: nie można zapisać kalibracji TT: {2}</translation>
    </message>
    <message>
        <source>Cylinder radius</source>
        <translation>Promień cylindra</translation>
    </message>
    <message>
        <source>Rotary-axis coordinates in the subprogram: 0 degrees, 1 mm/inch</source>
        <translation>Współrzędne osi obrotowej w podprogramie: 0 stopnie, 1 mm/cal</translation>
    </message>
    <message>
        <source>Ridge width</source>
        <translation>Szerokość mostka</translation>
    </message>
    <message>
        <source>Tolerance of the slot walls (0: no re-machining)</source>
        <translation>Tolerancja ścianek rowka (0: bez obróbki dodatkowej)</translation>
    </message>
    <message>
        <source>cycle {1}: the cylinder radius Q16 must be greater than 0</source>
        <translation>cykl {1}: promień cylindra Q16 musi być większy od 0</translation>
    </message>
    <message>
        <source>cycle {1}: program the contour subprogram with radius compensation RL or RR</source>
        <translation>cykl {1}: zaprogramuj podprogram konturu z korekcją promienia RL lub RR</translation>
    </message>
    <message>
        <source>cycle {1}: the centre line must be an open contour, not end where it starts</source>
        <translation>cykl {1}: linia środkowa musi być konturem otwartym, nie może kończyć się w punkcie początkowym</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE</source>
        <translation>POWIERZCHNIA CYLINDRA</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE SLOT</source>
        <translation>POWIERZCHNIA CYLINDRA ROWEK</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE RIDGE</source>
        <translation>POWIERZCHNIA CYLINDRA MOSTEK</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE CONTOUR</source>
        <translation>POWIERZCHNIA CYLINDRA KONTUR</translation>
    </message>
    <message>
        <source>a thread cannot be cut on the development of a cylinder</source>
        <translation>na rozwinięciu cylindra nie można naciąć gwintu</translation>
    </message>
    <message>
        <source>cycle {1} needs a rotary table described in the machine file ([kinematics], docs/machine-config.md)</source>
        <translation>cykl {1} wymaga stołu obrotowego opisanego w pliku maszyny ([kinematics], docs/machine-config.md)</translation>
    </message>
    <message>
        <source>cycle {1} cannot run with M128/FUNCTION TCPM active</source>
        <translation>cykl {1} nie może działać przy aktywnym M128/FUNCTION TCPM</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is an output of this run and cannot be read</source>
        <translation>&apos;{1}&apos; jest wyjściem tego przebiegu i nie może być odczytany</translation>
    </message>
    <message>
        <source>TYPE OF DIMENSION</source>
        <translation>RODZAJ WYMIAROWANIA</translation>
    </message>
    <message>
        <source>RIDGE WIDTH</source>
        <translation>SZEROKOŚĆ MOSTKA</translation>
    </message>
    <message>
        <source>the contour subprogram {1} has no contour</source>
        <translation>podprogram konturu {1} nie zawiera konturu</translation>
    </message>
    <message>
        <source>Dwell time at the bottom</source>
        <translation>Czas przerwy na dnie</translation>
    </message>
    <message>
        <source>PECKING</source>
        <translation>WIERCENIE GŁĘBOKIE</translation>
    </message>
    <message>
        <source>TAPPING</source>
        <translation>GWINTOWANIE</translation>
    </message>
    <message>
        <source>Set-up clearance: tool tip at the start to surface</source>
        <translation>Odstęp bezpieczeństwa: ostrze narzędzia w punkcie startu do powierzchni</translation>
    </message>
    <message>
        <source>Depth from the surface (the sign gives the direction)</source>
        <translation>Głębokość od powierzchni (znak określa kierunek)</translation>
    </message>
    <message>
        <source>Feed rate</source>
        <translation>Posuw</translation>
    </message>
    <message>
        <source>Feed rate for plunging (none: the milling feed)</source>
        <translation>Posuw wcięcia (brak: posuw frezowania)</translation>
    </message>
    <message>
        <source>Direction: DR+ counterclockwise, DR- clockwise</source>
        <translation>Kierunek: DR+ przeciwnie do ruchu wskazówek zegara, DR- zgodnie</translation>
    </message>
    <message>
        <source>First side length (parallel to the first axis)</source>
        <translation>Długość pierwszego boku (równoległa do pierwszej osi)</translation>
    </message>
    <message>
        <source>Pocket radius</source>
        <translation>Promień kieszeni</translation>
    </message>
    <message>
        <source>cycle {1} has no sub-block {1}.{2}</source>
        <translation>cykl {1} nie ma podbloku {1}.{2}</translation>
    </message>
    <message>
        <source>cycle {1}: the tool axis must be perpendicular to the axis of rotary table {2} (tilt the table or the head first, e.g. with PLANE)</source>
        <translation>cykl {1}: oś narzędzia musi być prostopadła do osi stołu obrotowego {2} (najpierw nachyl stół lub głowicę, np. za pomocą PLANE)</translation>
    </message>
    <message>
        <source>PLANE AXIAL: {1} is not a rotary axis of the kinematics of this machine</source>
        <translation>PLANE AXIAL: {1} nie jest osią obrotową kinematyki tej maszyny</translation>
    </message>
    <message>
        <source>TCPM needs the rotary axes described in the machine file ([kinematics], e.g. --machine mill5)</source>
        <translation>TCPM wymaga osi obrotowych opisanych w pliku maszyny ([kinematics], np. --machine mill5)</translation>
    </message>
    <message>
        <source>How the rotary axes are built: none, one rotary table, a table on a tilting table, a swivel head and a table, or a fork head</source>
        <translation>Budowa osi obrotowych: brak, jeden stół obrotowy, stół na stole uchylnym, głowica uchylna i stół albo głowica widłowa</translation>
    </message>
    <message>
        <source>The tilting rotary axis (SEQ+/SEQ- choose its sign)</source>
        <translation>Uchylna oś obrotowa (SEQ+/SEQ- wybierają jej znak)</translation>
    </message>
    <message>
        <source>The second rotary axis: the table on the tilting table, the table of a head-table machine, the head axis carrying the fork</source>
        <translation>Druga oś obrotowa: stół na stole uchylnym, stół maszyny głowica-stół, oś głowicy niosąca widły</translation>
    </message>
    <message>
        <source>Head: X of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Głowica: X punktu obrotu głowicy od czoła wrzeciona, głowica w 0; zapisz head_pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Head: Y of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Głowica: Y punktu obrotu głowicy od czoła wrzeciona, głowica w 0; zapisz head_pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Head: Z of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Głowica: Z punktu obrotu głowicy od czoła wrzeciona, głowica w 0; zapisz head_pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>kinematics.primary is the tilting axis: A or B, not C</source>
        <translation>kinematics.primary to oś uchylna: A lub B, nie C</translation>
    </message>
    <message>
        <source>FK: {1} is not an axis of the working plane</source>
        <translation>FK: {1} nie jest osią płaszczyzny obróbki</translation>
    </message>
    <message>
        <source>G53 in a profile needs a G00 or G01 point in X, Z</source>
        <translation>G53 w profilu wymaga punktu G00 lub G01 w X, Z</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: it rises {3}° from the passes and the cutting angle CUTA allows {4}°</source>
        <translation>narzędzie T{1} nie sięga profilu w wierszu {2}: wznosi się o {3}° względem przejść, a kąt skrawania CUTA pozwala na {4}°</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: it descends {3}° into the material and CUTA + NOSEA leave {4}°</source>
        <translation>narzędzie T{1} nie sięga profilu w wierszu {2}: opada o {3}° w materiał, a CUTA + NOSEA pozostawiają {4}°</translation>
    </message>
    <message>
        <source>Exact radius of the calibration sphere</source>
        <translation>Dokładny promień kuli kalibracyjnej</translation>
    </message>
    <message>
        <source>Calibrate the length too: 0 no, 1 yes</source>
        <translation>Kalibrować także długość: 0 nie, 1 tak</translation>
    </message>
    <message>
        <source>Datum for the length: height of the sphere&apos;s centre</source>
        <translation>Punkt odniesienia długości: wysokość środka kuli</translation>
    </message>
    <message>
        <source>Number of points for the 3D calibration (0: none)</source>
        <translation>Liczba punktów kalibracji 3D (0: brak)</translation>
    </message>
    <message>
        <source>cycle {1}: the 3D calibration (Q455 &gt; 0, option 92) is not available; set Q455 = 0</source>
        <translation>cykl {1}: kalibracja 3D (Q455 &gt; 0, opcja 92) nie jest dostępna; ustaw Q455 = 0</translation>
    </message>
    <message>
        <source>CALIBRATE TS ON SPHERE</source>
        <translation>KALIBROWANIE TS NA KULI</translation>
    </message>
    <message>
        <source>Result parameter</source>
        <translation>Parametr wyniku</translation>
    </message>
    <message>
        <source>Probing angle</source>
        <translation>Kąt próbkowania</translation>
    </message>
    <message>
        <source>Maximum measuring path</source>
        <translation>Maksymalna droga pomiaru</translation>
    </message>
    <message>
        <source>Measuring feed</source>
        <translation>Posuw pomiarowy</translation>
    </message>
    <message>
        <source>Maximum retraction path</source>
        <translation>Maksymalna droga wycofania</translation>
    </message>
    <message>
        <source>Reference system: 0 active, 1 machine</source>
        <translation>Układ odniesienia: 0 aktywny, 1 maszyny</translation>
    </message>
    <message>
        <source>Error mode: 0 error if deflected at the start, 1 status -1</source>
        <translation>Tryb błędu: 0 błąd przy wychyleniu na starcie, 1 status -1</translation>
    </message>
    <message>
        <source>{1}.{2}: the probing axis X, Y or Z expected</source>
        <translation>{1}.{2}: oczekiwano osi próbkowania X, Y lub Z</translation>
    </message>
    <message>
        <source>{1}.{2}: the probing direction IX, IY, IZ is zero</source>
        <translation>{1}.{2}: kierunek próbkowania IX, IY, IZ jest zerowy</translation>
    </message>
    <message>
        <source>G55: the probing axis with its direction (X-, Y+ ...) expected</source>
        <translation>G55: oczekiwano osi próbkowania z kierunkiem (X-, Y+ ...)</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): X of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Kula kalibracyjna (cykl 460): X jej środka w zaprogramowanym układzie półfabrykatu; zapis centre = [x, y, z]</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): Y of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Kula kalibracyjna (cykl 460): Y jej środka w zaprogramowanym układzie półfabrykatu; zapis centre = [x, y, z]</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): Z of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Kula kalibracyjna (cykl 460): Z jej środka w zaprogramowanym układzie półfabrykatu; zapis centre = [x, y, z]</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): its exact radius; 0: none</source>
        <translation>Kula kalibracyjna (cykl 460): jej dokładny promień; 0: brak</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: the arc&apos;s radius {3} is smaller than the nose radius {4}</source>
        <translation>narzędzie T{1} nie sięga profilu w wierszu {2}: promień łuku {3} jest mniejszy niż promień naroża {4}</translation>
    </message>
    <message>
        <source>a label number from 1 to 65535 or a name expected</source>
        <translation>oczekiwano numeru etykiety od 1 do 65535 lub nazwy</translation>
    </message>
    <message>
        <source>cycle {1}: {2} expected in {1}.{3}</source>
        <translation>cykl {1}: oczekiwano {2} w {1}.{3}</translation>
    </message>
    <message>
        <source>FUNCTION MODE MILL: the machine file sets the kinematics; &apos;{1}&apos; cannot be selected</source>
        <translation>FUNCTION MODE MILL: kinematykę ustala plik maszyny; nie można wybrać &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>FUNCTION MODE TURN: this machine has no turning mode</source>
        <translation>FUNCTION MODE TURN: ta maszyna nie ma trybu toczenia</translation>
    </message>
    <message>
        <source>FUNCTION MODE: MILL or TURN expected</source>
        <translation>FUNCTION MODE: oczekiwano MILL lub TURN</translation>
    </message>
    <message>
        <source>M120 LA: a whole number of blocks from 0 to 99</source>
        <translation>M120 LA: całkowita liczba bloków od 0 do 99</translation>
    </message>
    <message>
        <source>CALL SELECTED PGM: no program was selected with SEL PGM</source>
        <translation>CALL SELECTED PGM: nie wybrano programu poleceniem SEL PGM</translation>
    </message>
    <message>
        <source>cycle {1}: no room for the helical plunge, and the reciprocating plunge needs the tool&apos;s LCUTS (pre-drill with cycle 21 or use a centre-cutting tool)</source>
        <translation>cykl {1}: brak miejsca na wcinanie po linii śrubowej, a wcinanie ruchem wahadłowym wymaga LCUTS narzędzia (nawiercić wstępnie cyklem 21 lub użyć narzędzia tnącego przez środek)</translation>
    </message>
    <message>
        <source>Axis of the first side length: 0 main axis, 1 secondary axis</source>
        <translation>Oś pierwszej długości boku: 0 oś główna, 1 oś pomocnicza</translation>
    </message>
    <message>
        <source>cycle {1}: the tool diameter must be at least half the slot width</source>
        <translation>cykl {1}: średnica narzędzia musi wynosić co najmniej połowę szerokości rowka</translation>
    </message>
    <message>
        <source>cycle {1}: the slot is shorter than it is wide</source>
        <translation>cykl {1}: rowek jest krótszy niż szeroki</translation>
    </message>
    <message>
        <source>manual probing: call the touch probe with TOOL CALL first (MDI)</source>
        <translation>pomiar ręczny: najpierw wywołaj sondę przez TOOL CALL (MDI)</translation>
    </message>
    <message>
        <source>manual probing: tool {1} is not in TOOL.T</source>
        <translation>pomiar ręczny: narzędzia {1} nie ma w TOOL.T</translation>
    </message>
    <message>
        <source>manual probing: probe {1} is not in tchprobe.tp</source>
        <translation>pomiar ręczny: sondy {1} nie ma w tchprobe.tp</translation>
    </message>
    <message>
        <source>In ISO programs cycle %1 takes only %2: leave the other fields empty</source>
        <translation>W programach ISO cykl %1 przyjmuje tylko %2: pozostałe pola zostaw puste</translation>
    </message>
    <message>
        <source>the rotary axes turn too far in this block to keep the tool tip on the path; split the block</source>
        <translation>osie obrotowe obracają się w tym bloku zbyt daleko, aby utrzymać wierzchołek narzędzia na torze; podziel blok</translation>
    </message>
    <message>
        <source>M94 {1}: the machine has no rotary axis {1}</source>
        <translation>M94 {1}: maszyna nie ma osi obrotowej {1}</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest X, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Symulowany półfabrykat programu bez BLK FORM: jego najmniejsze X, współrzędne przedmiotu presetu pliku maszyny; zapisz min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest Y, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Symulowany półfabrykat programu bez BLK FORM: jego najmniejsze Y, współrzędne przedmiotu presetu pliku maszyny; zapisz min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest Z, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Symulowany półfabrykat programu bez BLK FORM: jego najmniejsze Z, współrzędne przedmiotu presetu pliku maszyny; zapisz min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest X, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Symulowany półfabrykat programu bez BLK FORM: jego największe X, współrzędne przedmiotu presetu pliku maszyny; zapisz max = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest Y, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Symulowany półfabrykat programu bez BLK FORM: jego największe Y, współrzędne przedmiotu presetu pliku maszyny; zapisz max = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest Z, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Symulowany półfabrykat programu bez BLK FORM: jego największe Z, współrzędne przedmiotu presetu pliku maszyny; zapisz max = [x, y, z]</translation>
    </message>
    <message>
        <source>tool length touch-off: no tool in the spindle</source>
        <translation>Pomiar długości przez dotknięcie: brak narzędzia we wrzecionie</translation>
    </message>
    <message>
        <source>tool length touch-off: tool {1} is not in TOOL.T</source>
        <translation>Pomiar długości przez dotknięcie: narzędzia {1} nie ma w TOOL.T</translation>
    </message>
    <message>
        <source>Positioning: TURN, MOVE (DIST) or STAY</source>
        <translation>Pozycjonowanie: TURN, MOVE (DIST) lub STAY</translation>
    </message>
    <message>
        <source>Retract along the tool axis first: MAX or mm</source>
        <translation>Najpierw odjazd wzdłuż osi narzędzia: MAX lub mm</translation>
    </message>
    <message>
        <source>MOVE: distance of the tool tip from the centre of rotation</source>
        <translation>MOVE: odległość wierzchołka narzędzia od środka obrotu</translation>
    </message>
    <message>
        <source>Feed rate of the positioning, or FMAX</source>
        <translation>Posuw pozycjonowania lub FMAX</translation>
    </message>
    <message>
        <source>Solution: SEQ+ or SEQ- (empty: the machine&apos;s)</source>
        <translation>Rozwiązanie: SEQ+ lub SEQ- (puste: maszyny)</translation>
    </message>
    <message>
        <source>Transformation: COORD ROT or TABLE ROT</source>
        <translation>Transformacja: COORD ROT lub TABLE ROT</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not allowed here</source>
        <translation>%1: „%2” jest tu niedozwolone</translation>
    </message>
    <message>
        <source>Spatial angle A [°]</source>
        <translation>Kąt przestrzenny A [°]</translation>
    </message>
    <message>
        <source>Spatial angle B [°]</source>
        <translation>Kąt przestrzenny B [°]</translation>
    </message>
    <message>
        <source>Spatial angle C [°]</source>
        <translation>Kąt przestrzenny C [°]</translation>
    </message>
    <message>
        <source>Projected angle in the principal plane [°]</source>
        <translation>Kąt rzutowania w płaszczyźnie głównej [°]</translation>
    </message>
    <message>
        <source>Projected angle in the minor plane [°]</source>
        <translation>Kąt rzutowania w płaszczyźnie pomocniczej [°]</translation>
    </message>
    <message>
        <source>Rotation in the tilted plane [°]</source>
        <translation>Obrót w nachylonej płaszczyźnie [°]</translation>
    </message>
    <message>
        <source>Precession angle [°]</source>
        <translation>Kąt precesji [°]</translation>
    </message>
    <message>
        <source>Nutation angle [°]</source>
        <translation>Kąt nutacji [°]</translation>
    </message>
    <message>
        <source>Rotation angle [°]</source>
        <translation>Kąt obrotu [°]</translation>
    </message>
    <message>
        <source>Base vector (X direction)</source>
        <translation>Wektor bazowy (kierunek X)</translation>
    </message>
    <message>
        <source>Normal vector</source>
        <translation>Wektor normalny</translation>
    </message>
    <message>
        <source>First point (origin of X)</source>
        <translation>Pierwszy punkt (początek X)</translation>
    </message>
    <message>
        <source>Second point (on the X axis)</source>
        <translation>Drugi punkt (na osi X)</translation>
    </message>
    <message>
        <source>Third point (in the plane)</source>
        <translation>Trzeci punkt (w płaszczyźnie)</translation>
    </message>
    <message>
        <source>Axis of the incremental spatial angle</source>
        <translation>Oś przyrostowego kąta przestrzennego</translation>
    </message>
    <message>
        <source>Incremental angle [°]</source>
        <translation>Kąt przyrostowy [°]</translation>
    </message>
    <message>
        <source>Axis angle [°] (empty: not moved)</source>
        <translation>Kąt osi [°] (puste: bez ruchu)</translation>
    </message>
    <message>
        <source>Feed rate at the tool tip</source>
        <translation>Posuw na wierzchołku narzędzia</translation>
    </message>
    <message>
        <source>Rotary axes: machine positions</source>
        <translation>Osie obrotowe: pozycje maszyny</translation>
    </message>
    <message>
        <source>Path: the axes interpolate linearly</source>
        <translation>Tor: osie interpolują liniowo</translation>
    </message>
    <message>
        <source>Reference point: the tool tip</source>
        <translation>Punkt odniesienia: wierzchołek narzędzia</translation>
    </message>
    <message>
        <source>Feed rate of the compensating moves</source>
        <translation>Posuw ruchów kompensacyjnych</translation>
    </message>
    <message>
        <source>Program name, e.g. PART or TNC:\DIR\PART.H</source>
        <translation>Nazwa programu, np. PART lub TNC:\DIR\PART.H</translation>
    </message>
    <message>
        <source>PLANE AXIAL: enter the angle of A, B or C</source>
        <translation>PLANE AXIAL: wprowadzić kąt A, B lub C</translation>
    </message>
    <message>
        <source>STAY moves nothing: leave MB, DIST and F empty</source>
        <translation>STAY niczego nie przesuwa: pozostawić MB, DIST i F puste</translation>
    </message>
    <message>
        <source>DIST belongs to MOVE</source>
        <translation>DIST należy do MOVE</translation>
    </message>
    <message>
        <source>stopped after {1} blocks: endless loop? (--max-blocks)</source>
        <translation>zatrzymano po {1} blokach: nieskończona pętla? (--max-blocks)</translation>
    </message>
    <message>
        <source>LN needs all of NX NY NZ, and TX TY TZ all or none</source>
        <translation>LN wymaga wszystkich NX NY NZ, a TX TY TZ wszystkich albo żadnego</translation>
    </message>
    <message>
        <source>FUNCTION TCPM: only F TCP|CONT, AXIS POS|SPAT, PATHCTRL AXIS|VECTOR and REFPNT TIP-TIP are supported, not &apos;{1}&apos;</source>
        <translation>FUNCTION TCPM: obsługiwane są tylko F TCP|CONT, AXIS POS|SPAT, PATHCTRL AXIS|VECTOR i REFPNT TIP-TIP, nie &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>LN compensates along the surface normal: switch the radius compensation off (R0) first</source>
        <translation>LN koryguje wzdłuż normalnej do powierzchni: najpierw wyłącz korekcję promienia (R0)</translation>
    </message>
    <message>
        <source>LN: a vector NX NY NZ or TX TY TZ has no length</source>
        <translation>LN: wektor NX NY NZ lub TX TY TZ ma zerową długość</translation>
    </message>
    <message>
        <source>LN: the rotary axes of this machine cannot turn the tool along TX TY TZ</source>
        <translation>LN: osie obrotowe tej maszyny nie mogą obrócić narzędzia wzdłuż TX TY TZ</translation>
    </message>
    <message>
        <source>with TCPM on the program positions the rotary axes: tilt with STAY, or switch TCPM off first</source>
        <translation>przy aktywnym TCPM program pozycjonuje osie obrotowe: nachylaj z STAY albo najpierw wyłącz TCPM</translation>
    </message>
    <message>
        <source>AXIS SPAT: the rotary axes of this machine cannot turn the tool to the spatial angles A {1} B {2} C {3}</source>
        <translation>AXIS SPAT: osie obrotowe tej maszyny nie mogą obrócić narzędzia do kątów przestrzennych A {1} B {2} C {3}</translation>
    </message>
    <message>
        <source>the arc&apos;s radius {1} is smaller than the tool nose radius {2}: the nose cannot follow it</source>
        <translation>promień łuku {1} jest mniejszy niż promień naroża narzędzia {2}: naroże nie może za nim podążać</translation>
    </message>
    <message>
        <source>Pattern repeat cycle</source>
        <translation>Cykl powtarzania profilu</translation>
    </message>
    <message>
        <source>Stock removal cycle along X</source>
        <translation>Cykl zgrubny wzdłuż osi X</translation>
    </message>
    <message>
        <source>Stock removal cycle along Z</source>
        <translation>Cykl zgrubny wzdłuż osi Z</translation>
    </message>
    <message>
        <source>Turning cycle, straight sections</source>
        <translation>Cykl toczenia odcinków prostych</translation>
    </message>
    <message>
        <source>Facing cycle, straight sections</source>
        <translation>Cykl planowania odcinków prostych</translation>
    </message>
    <message>
        <source>Axial drilling / tapping cycle</source>
        <translation>Cykl wiercenia osiowego / gwintowania gwintownikiem</translation>
    </message>
    <message>
        <source>Turning cycle, curved sections</source>
        <translation>Cykl toczenia odcinków łukowych</translation>
    </message>
    <message>
        <source>Facing cycle, curved sections</source>
        <translation>Cykl planowania odcinków łukowych</translation>
    </message>
    <message>
        <source>Longitudinal threading cycle</source>
        <translation>Cykl gwintowania wzdłużnego</translation>
    </message>
    <message>
        <source>Face threading cycle</source>
        <translation>Cykl gwintowania czołowego</translation>
    </message>
    <message>
        <source>Grooving cycle along X</source>
        <translation>Cykl rowkowania wzdłuż osi X</translation>
    </message>
    <message>
        <source>the program check stopped after {1} blocks: endless loop?</source>
        <translation>sprawdzenie programu zatrzymało się po {1} blokach: nieskończona pętla?</translation>
    </message>
    <message>
        <source>Grooving cycle along Z</source>
        <translation>Cykl rowkowania wzdłuż osi Z</translation>
    </message>
    <message>
        <source>tapping and thread cutting follow the spindle along the tool axis: switch TCPM off first (M129 or FUNCTION RESET TCPM)</source>
        <translation>gwintowanie gwintownikiem i nacinanie gwintu podążają za wrzecionem wzdłuż osi narzędzia: najpierw wyłącz TCPM (M129 lub FUNCTION RESET TCPM)</translation>
    </message>
    <message>
        <source>cannot write the calibration log {1}: {2}</source>
        <translation>nie można zapisać protokołu kalibracji {1}: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the touch-probe table: {2}</source>
        <translation>cykl sondy {1}: nie można zapisać tabeli sond: {2}</translation>
    </message>
    <message>
        <source>{1} must be an array of two numbers [x, y] within +-10 mm, not {2}</source>
        <translation>{1} musi być tablicą dwóch liczb [x, y] w zakresie +-10 mm, a nie {2}</translation>
    </message>
    <message>
        <source>probe {1} is not in the touch-probe table</source>
        <translation>sondy {1} nie ma w tabeli sond</translation>
    </message>
    <message>
        <source>cannot add a column &quot;{1}&quot;</source>
        <translation>nie można dodać kolumny &quot;{1}&quot;</translation>
    </message>
    <message>
        <source>{1} is not allowed beside the polar coordinates PR/PA (only the tool axis may be programmed)</source>
        <translation>{1} nie jest dozwolone obok współrzędnych biegunowych PR/PA (można programować tylko oś narzędzia)</translation>
    </message>
    <message>
        <source>QR{1} = &apos;{2}&apos; is not a finite number</source>
        <translation>QR{1} = &apos;{2}&apos; nie jest liczbą skończoną</translation>
    </message>
    <message>
        <source>column {1} needs a whole number from 0 to {2}, not &quot;{3}&quot;</source>
        <translation>kolumna {1} wymaga liczby całkowitej od 0 do {2}, nie &quot;{3}&quot;</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the probe {2} cannot be turned to each probing direction (angle tracking of cycle 441, Q399 = 1)</source>
        <translation>cykl sondy {1}: sondy {2} nie można obrócić w każdym kierunku próbkowania (nadążanie kątowe cyklu 441, Q399 = 1)</translation>
    </message>
    <message>
        <source>column TYPE: unknown probe &quot;{1}&quot; (known: {2})</source>
        <translation>kolumna TYPE: nieznana sonda &quot;{1}&quot; (znane: {2})</translation>
    </message>
    <message>
        <source>TRACK ON needs a probe the spindle can turn to any angle; {1} cannot be</source>
        <translation>TRACK ON wymaga sondy, którą wrzeciono może obrócić o dowolny kąt; {1} tego nie umożliwia</translation>
    </message>
    <message>
        <source>LN: the tool is larger than the CAM system&apos;s (DR {1}, DR2 {2} from the tool table and TOOL CALL): program M107 to permit positive oversizes</source>
        <translation>LN: narzędzie jest większe niż narzędzie systemu CAM (DR {1}, DR2 {2} z tabeli narzędzi i TOOL CALL): zaprogramuj M107, aby dopuścić dodatnie naddatki</translation>
    </message>
    <message>
        <source>LN: the corner radius R2+DR2 {1} must lie between 0 (end mill) and the radius R+DR {2} (ball cutter)</source>
        <translation>LN: promień naroża R2+DR2 {1} musi leżeć między 0 (frez walcowy) a promieniem R+DR {2} (frez kulisty)</translation>
    </message>
    <message>
        <source>LN: the rotary axes of this machine cannot turn the tool along the surface normal NX NY NZ</source>
        <translation>LN: osie obrotowe tej maszyny nie mogą obrócić narzędzia wzdłuż wektora normalnego powierzchni NX NY NZ</translation>
    </message>
    <message>
        <source>LN is the conversational straight line with 3D tool compensation; in ISO write G01 X Y Z NX NY NZ [TX TY TZ]</source>
        <translation>LN to prosta z korekcją 3D narzędzia w języku dialogowym; w ISO należy zapisać G01 X Y Z NX NY NZ [TX TY TZ]</translation>
    </message>
    <message>
        <source>surface vectors NX NY NZ TX TY TZ belong to a straight line G00/G01</source>
        <translation>wektory powierzchni NX NY NZ TX TY TZ należą do prostej G00/G01</translation>
    </message>
    <message>
        <source>SL cycles (21-25, 275, 276) end back at the position before the cycle (the TNC&apos;s posAfterContPocket = PosBeforeMachining); false: at the clearance height Q7, the tool axis only (ToolAxClearanceHeight)</source>
        <translation>Cykle SL (21-25, 275, 276) kończą się z powrotem w pozycji sprzed cyklu (posAfterContPocket = PosBeforeMachining sterowania TNC); false: na bezpiecznej wysokości Q7, tylko w osi narzędzia (ToolAxClearanceHeight)</translation>
    </message>
    <message>
        <source>the simulated part holds the cuts of the first {1} tool moves only: later moves removed no material</source>
        <translation>symulowany przedmiot zawiera tylko skrawanie pierwszych {1} ruchów narzędzia: późniejsze ruchy nie usunęły materiału</translation>
    </message>
    <message>
        <source>Allowance in the 1st axis left by roughing</source>
        <translation>Naddatek w 1. osi pozostawiony przez obróbkę zgrubną</translation>
    </message>
    <message>
        <source>POCKET FINISHING</source>
        <translation>WYKAŃCZANIE KIESZENI</translation>
    </message>
    <message>
        <source>STUD FINISHING</source>
        <translation>WYKAŃCZANIE CZOPU</translation>
    </message>
    <message>
        <source>CIRCULAR POCKET FINISHING</source>
        <translation>WYKAŃCZANIE KIESZENI OKRĄGŁEJ</translation>
    </message>
    <message>
        <source>CIRCULAR STUD FINISHING</source>
        <translation>WYKAŃCZANIE CZOPU OKRĄGŁEGO</translation>
    </message>
    <message>
        <source>Number of cuts</source>
        <translation>Liczba przejść</translation>
    </message>
    <message>
        <source>Feed rate to the starting point in the tool axis</source>
        <translation>Posuw do punktu startu w osi narzędzia</translation>
    </message>
    <message>
        <source>Feed rate for stepover (FMAX: rapid)</source>
        <translation>Posuw dla przesunięcia bocznego (FMAX: bieg szybki)</translation>
    </message>
    <message>
        <source>MULTIPASS MILLING</source>
        <translation>FREZOWANIE WIELOPRZEJŚCIOWE</translation>
    </message>
    <message>
        <source>SLOT RECIP. PLNG.</source>
        <translation>ROWEK RUCHEM WAHADŁOWYM</translation>
    </message>
    <message>
        <source>Starting point in the 3rd axis</source>
        <translation>Punkt startu w 3. osi</translation>
    </message>
    <message>
        <source>2nd point in the 1st axis</source>
        <translation>2. punkt w 1. osi</translation>
    </message>
    <message>
        <source>2nd point in the 2nd axis</source>
        <translation>2. punkt w 2. osi</translation>
    </message>
    <message>
        <source>2nd point in the 3rd axis</source>
        <translation>2. punkt w 3. osi</translation>
    </message>
    <message>
        <source>3rd point in the 1st axis</source>
        <translation>3. punkt w 1. osi</translation>
    </message>
    <message>
        <source>3rd point in the 2nd axis</source>
        <translation>3. punkt w 2. osi</translation>
    </message>
    <message>
        <source>3rd point in the 3rd axis</source>
        <translation>3. punkt w 3. osi</translation>
    </message>
    <message>
        <source>4th point in the 1st axis</source>
        <translation>4. punkt w 1. osi</translation>
    </message>
    <message>
        <source>4th point in the 2nd axis</source>
        <translation>4. punkt w 2. osi</translation>
    </message>
    <message>
        <source>4th point in the 3rd axis</source>
        <translation>4. punkt w 3. osi</translation>
    </message>
    <message>
        <source>RULED SURFACE</source>
        <translation>POWIERZCHNIA PROSTOKREŚLNA</translation>
    </message>
    <message>
        <source>cycle {1}: the two points of a measured line coincide</source>
        <translation>cykl {1}: oba punkty mierzonej prostej pokrywają się</translation>
    </message>
    <message>
        <source>mm (radius)</source>
        <translation>mm (promień)</translation>
    </message>
    <message>
        <source>collision: a rapid move runs into the material of the blank</source>
        <translation>kolizja: ruch szybki wjeżdża w materiał półfabrykatu</translation>
    </message>
    <message>
        <source>ready</source>
        <comment>machine state</comment>
        <translation>gotowa</translation>
    </message>
    <message>
        <source>running</source>
        <comment>machine state</comment>
        <translation>w toku</translation>
    </message>
    <message>
        <source>feed hold</source>
        <comment>machine state</comment>
        <translation>zatrzymanie posuwu</translation>
    </message>
    <message>
        <source>stopped</source>
        <comment>machine state</comment>
        <translation>zatrzymana</translation>
    </message>
    <message>
        <source>jogging</source>
        <comment>machine state</comment>
        <translation>przesuw ręczny</translation>
    </message>
    <message>
        <source>homing</source>
        <comment>machine state</comment>
        <translation>bazowanie</translation>
    </message>
    <message>
        <source>stopping</source>
        <comment>machine state</comment>
        <translation>zatrzymywanie</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <comment>machine state</comment>
        <translation>wyłączenie awaryjne</translation>
    </message>
    <message>
        <source>fault</source>
        <comment>machine state</comment>
        <translation>usterka</translation>
    </message>
    <message>
        <source>no machine</source>
        <comment>machine state</comment>
        <translation>brak maszyny</translation>
    </message>
    <message>
        <source>Block {1}: the machine has no axis {2}.</source>
        <translation>Blok {1}: maszyna nie ma osi {2}.</translation>
    </message>
    <message>
        <source>Block {1}: the move would take axis {2} to {3} (machine coordinates), beyond its soft limit {4}; the program is not run past this block.</source>
        <translation>Blok {1}: ruch przesunąłby oś {2} do {3} (współrzędne maszynowe), poza jej programowy wyłącznik krańcowy {4}; program nie jest wykonywany poza ten blok.</translation>
    </message>
    <message>
        <source>Block {1}: feed per revolution with the spindle stopped.</source>
        <translation>Blok {1}: posuw na obrót przy zatrzymanym wrzecionie.</translation>
    </message>
    <message>
        <source>Block {1}: feed move without a feed rate.</source>
        <translation>Blok {1}: ruch roboczy bez prędkości posuwu.</translation>
    </message>
    <message>
        <source>Block {1}: {2} = {3} is outside the range of the control; the program is not run past this block.</source>
        <translation>Blok {1}: {2} = {3} jest poza zakresem sterowania; program nie jest wykonywany poza ten blok.</translation>
    </message>
    <message>
        <source>Block {1}: the arc&apos;s end point is {2} mm off its circle.</source>
        <translation>Blok {1}: punkt końcowy łuku leży {2} mm od jego okręgu.</translation>
    </message>
    <message>
        <source>Block {1}: threads with a variable lead (G34) cannot be executed yet.</source>
        <translation>Blok {1}: gwintów o zmiennym skoku (G34) nie można jeszcze wykonać.</translation>
    </message>
    <message>
        <source>Block {1}: spindle-synchronised move without a lead or a spindle speed.</source>
        <translation>Blok {1}: ruch zsynchronizowany z wrzecionem bez skoku lub prędkości wrzeciona.</translation>
    </message>
    <message>
        <source>Cannot write the samples file {1}.</source>
        <translation>Nie można zapisać pliku próbek {1}.</translation>
    </message>
    <message>
        <source>Motion error {1} at line {2}.</source>
        <translation>Błąd ruchu {1} w wierszu {2}.</translation>
    </message>
    <message>
        <source>Emergency stop at {1} s after the start (the button was pressed): every axis and the spindle were stopped and the program was aborted.</source>
        <translation>Wyłączenie awaryjne {1} s po starcie (naciśnięto przycisk): wszystkie osie i wrzeciono zostały zatrzymane, a program przerwany.</translation>
    </message>
    <message>
        <source>The simulation reached its limit of {1} s of simulated time before the program&apos;s motion ended: the run stops here.</source>
        <translation>Symulacja osiągnęła swój limit {1} s czasu symulowanego, zanim ruch programu się zakończył: przebieg kończy się tutaj.</translation>
    </message>
    <message>
        <source>cycle {1}: a rotation measured in the ZX or YZ plane (Q1139 = {2}) turns about X or Y; only a basic rotation about the tool axis can be accepted (Q1121 = 0)</source>
        <translation>cykl {1}: obrót zmierzony w płaszczyźnie ZX lub YZ (Q1139 = {2}) jest obrotem wokół X lub Y; przejąć można tylko obrót podstawowy wokół osi narzędzia (Q1121 = 0)</translation>
    </message>
    <message>
        <source>cycle {1}: Q{2} is given as an actual position, but neither edge is probed along that axis</source>
        <translation>cykl {1}: Q{2} podano jako pozycję rzeczywistą, ale żadna z krawędzi nie jest próbkowana wzdłuż tej osi</translation>
    </message>
    <message>
        <source>Direction of the extrusion: 1 main axis, 2 secondary, 3 tool axis</source>
        <translation>Kierunek wyciągnięcia: 1 oś główna, 2 oś pomocnicza, 3 oś narzędzia</translation>
    </message>
    <message>
        <source>Length of the extrusion (incremental, the sign gives the way)</source>
        <translation>Długość wyciągnięcia (przyrostowo, znak określa kierunek)</translation>
    </message>
    <message>
        <source>Number of further touch points along the extrusion</source>
        <translation>Liczba dalszych punktów próbkowania wzdłuż wyciągnięcia</translation>
    </message>
    <message>
        <source>Extrusion active for: 0 the next 14xx cycle, 1 all following</source>
        <translation>Wyciągnięcie aktywne dla: 0 następnego cyklu 14xx, 1 wszystkich następnych</translation>
    </message>
    <message>
        <source>PROBING EXTRUSION</source>
        <translation>PRÓBKOWANIE WYCIĄGNIĘCIA</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) takes no actual position (nominal@actual is for the nominal positions of a 14xx cycle)</source>
        <translation>{1}: parametr {2} ({3}) nie przyjmuje pozycji rzeczywistej (zadana@rzeczywista dotyczy pozycji zadanych cyklu 14xx)</translation>
    </message>
    <message>
        <source>the probe stopped {1} mm beyond its touch point, more than its stylus can be deflected ({2} mm): lower the probing feed F in tchprobe.tp</source>
        <translation>sonda zatrzymała się {1} mm za punktem próbkowania, dalej niż może się wychylić jej trzpień ({2} mm): zmniejsz posuw próbkowania F w tchprobe.tp</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the simulated tools: {2}</source>
        <translation>cykl sondy {1}: nie można zapisać symulowanych narzędzi: {2}</translation>
    </message>
    <message>
        <source>cycle 1416 (semi-automatic mode): position the probe before touch point {1} of edge {2}, within {3} mm of the edge, probing at {4} degrees in the plane; then NC start</source>
        <translation>cykl 1416 (tryb półautomatyczny): ustaw sondę przed punktem pomiarowym {1} krawędzi {2}, nie dalej niż {3} mm od krawędzi, kierunek próbkowania {4} stopni w płaszczyźnie; następnie NC-start</translation>
    </message>
    <message>
        <source>cycle {1}: the semi-automatic mode (&apos;?&apos;) cannot repeat its touches along an extrusion (cycle 1493)</source>
        <translation>cykl {1}: tryb półautomatyczny (&apos;?&apos;) nie może powtarzać próbkowań wzdłuż ekstruzji (cykl 1493)</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) cannot be unknown (&apos;?&apos; is for the nominal positions of a 14xx cycle)</source>
        <translation>{1}: parametr {2} ({3}) nie może być nieznany (&apos;?&apos; jest dla pozycji nominalnych cyklu 14xx)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::BlockName</name>
    <message>
        <source>line %1</source>
        <translation>wiersz %1</translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation>Wiersz %1</translation>
    </message>
    <message>
        <source>Block %1</source>
        <translation>Blok %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::BlockPrompt</name>
    <message>
        <source>Line</source>
        <translation>Wiersz</translation>
    </message>
    <message>
        <source>Block number</source>
        <translation>Numer bloku</translation>
    </message>
    <message>
        <source>Block number N</source>
        <translation>Numer bloku N</translation>
    </message>
    <message>
        <source>The program has no block %1</source>
        <translation>Program nie ma bloku %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineRows</name>
    <message>
        <source>Increment
continuous</source>
        <translation>Krok
ciągły</translation>
    </message>
    <message>
        <source>Increment
%1 mm</source>
        <translation>Krok
%1 mm</translation>
    </message>
    <message>
        <source>Home
all</source>
        <translation>Bazuj
wszystkie</translation>
    </message>
    <message>
        <source>Spindle
on</source>
        <translation>Wrzeciono
wł.</translation>
    </message>
    <message>
        <source>Spindle
off</source>
        <translation>Wrzeciono
wył.</translation>
    </message>
    <message>
        <source>NC
start</source>
        <translation>NC
start</translation>
    </message>
    <message>
        <source>NC stop
(feed hold)</source>
        <translation>NC stop
(stop posuwu)</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Wznów</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <source>Start at
block</source>
        <translation>Start od
bloku</translation>
    </message>
    <message>
        <source>Single block
on</source>
        <translation>Pojedynczy blok
wł.</translation>
    </message>
    <message>
        <source>Single block
off</source>
        <translation>Pojedynczy blok
wył.</translation>
    </message>
    <message>
        <source>Execute
block</source>
        <translation>Wykonaj
blok</translation>
    </message>
    <message>
        <source>Set preset</source>
        <translation>Ustaw punkt odniesienia</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Oś</translation>
    </message>
    <message>
        <source>Position of %1 at the current point</source>
        <translation>Pozycja %1 w bieżącym punkcie</translation>
    </message>
    <message>
        <source>Handwheel
axis %1</source>
        <translation>Kółko ręczne
oś %1</translation>
    </message>
    <message>
        <source>Step
x%1</source>
        <translation>Krok
x%1</translation>
    </message>
    <message>
        <source>Handwheel
-</source>
        <translation>Kółko ręczne
-</translation>
    </message>
    <message>
        <source>Handwheel
+</source>
        <translation>Kółko ręczne
+</translation>
    </message>
    <message>
        <source>Coolant
on</source>
        <translation>Chłodziwo
wł.</translation>
    </message>
    <message>
        <source>Coolant
off</source>
        <translation>Chłodziwo
wył.</translation>
    </message>
    <message>
        <source>Set
preset</source>
        <translation>Ustaw punkt
odniesienia</translation>
    </message>
    <message>
        <source>Spindle speed</source>
        <translation>Prędkość obrotowa wrzeciona</translation>
    </message>
    <message>
        <source>S in rpm (%1 to %2)</source>
        <translation>S w obr/min (%1 do %2)</translation>
    </message>
    <message>
        <source>Probing: the touches give no result</source>
        <translation>Pomiar: punkty pomiarowe nie dają wyniku</translation>
    </message>
    <message>
        <source>Probing ROT</source>
        <translation>Pomiar ROT</translation>
    </message>
    <message>
        <source>Basic rotation in degrees (OK writes it to the preset table)</source>
        <translation>Obrót podstawowy w stopniach (OK zapisuje go w tabeli punktów bazowych)</translation>
    </message>
    <message>
        <source>Probing CC: diameter %1 mm</source>
        <translation>Pomiar CC: średnica %1 mm</translation>
    </message>
    <message>
        <source>Probing</source>
        <translation>Pomiar</translation>
    </message>
    <message>
        <source>Probed %1 = %2: the datum value there</source>
        <translation>Zmierzono %1 = %2: wartość punktu bazowego w tym miejscu</translation>
    </message>
    <message>
        <source>Probing
ROT</source>
        <translation>Pomiar
ROT</translation>
    </message>
    <message>
        <source>Probing
POS</source>
        <translation>Pomiar
POS</translation>
    </message>
    <message>
        <source>Probing
P</source>
        <translation>Pomiar
P</translation>
    </message>
    <message>
        <source>Probing
CC</source>
        <translation>Pomiar
CC</translation>
    </message>
    <message>
        <source>Direction
%1</source>
        <translation>Kierunek
%1</translation>
    </message>
    <message>
        <source>Tool calibration</source>
        <translation>Kalibracja narzędzia</translation>
    </message>
    <message>
        <source>Tool offset D</source>
        <translation>Korekcja narzędzia D</translation>
    </message>
    <message>
        <source>Axis touched</source>
        <translation>Dotknięta oś</translation>
    </message>
    <message>
        <source>Position of %1 where the tool touches</source>
        <translation>Pozycja %1 w miejscu styku narzędzia</translation>
    </message>
    <message>
        <source>Tool
calibration</source>
        <translation>Kalibracja
narzędzia</translation>
    </message>
    <message>
        <source>Touch %1
%2/%3</source>
        <translation>Dotknij %1
%2/%3</translation>
    </message>
    <message>
        <source>Tool length
touch-off</source>
        <translation>Długość
przez dotyk</translation>
    </message>
    <message>
        <source>Tool length touch-off</source>
        <translation>Pomiar długości przez dotknięcie</translation>
    </message>
    <message>
        <source>Z of the surface the tool touches</source>
        <translation>Z powierzchni, której dotyka narzędzie</translation>
    </message>
    <message>
        <source>Probing PL: A %1 degrees, B %2 degrees</source>
        <translation>Pomiar PL: A %1 stopni, B %2 stopni</translation>
    </message>
    <message>
        <source>Probing
PL</source>
        <translation>Pomiar
PL</translation>
    </message>
    <message>
        <source>Diameter %1 at the current point</source>
        <translation>Średnica %1 w bieżącym punkcie</translation>
    </message>
    <message>
        <source>Diameter %1 where the tool touches</source>
        <translation>Średnica %1 w miejscu styku narzędzia</translation>
    </message>
</context>
<context>
    <name>kerf::ui::RenumberPrompt</name>
    <message>
        <source>Renumber blocks</source>
        <translation>Przenumeruj bloki</translation>
    </message>
    <message>
        <source>First block number N</source>
        <translation>Pierwszy numer bloku N</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Krok</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 names a label through a parameter, which could not follow it</source>
        <translation>Bloki nie zostały przenumerowane: wiersz %1 wskazuje etykietę przez parametr, który nie mógłby za nią podążyć</translation>
    </message>
    <message>
        <source>Blocks not renumbered: the profile of the cycle in line %1 would start or end at N%2; G66, G68 and G69 take labels of 4 digits</source>
        <translation>Bloki nie zostały przenumerowane: kontur cyklu w wierszu %1 zaczynałby się lub kończył na N%2; G66, G68 i G69 przyjmują etykiety 4-cyfrowe</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 would get N%2, beyond N99999999</source>
        <translation>Bloki nie zostały przenumerowane: wiersz %1 otrzymałby N%2, powyżej N99999999</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 would get N%2, which line %3 carries already; the new line has no block number</source>
        <translation>Bloki nie zostały przenumerowane: wiersz %1 otrzymałby N%2, który ma już wiersz %3; nowy wiersz nie ma numeru bloku</translation>
    </message>
</context>
</TS>
