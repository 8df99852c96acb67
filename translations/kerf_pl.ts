<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pl_PL">
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
        <source>Tables (.T .TCH .PR .D .PNT .TAB)</source>
        <translation>Tabele (.T .TCH .PR .D .PNT .TAB)</translation>
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
        <source>Graphics</source>
        <translation>Grafika</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Positions: %1</source>
        <translation>Pozycje: %1</translation>
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
        <source>Preset
table</source>
        <translation>Tabela punktów
odniesienia</translation>
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
        <source>Go to
line</source>
        <translation>Idź do
wiersza</translation>
    </message>
    <message>
        <source>Go to line</source>
        <translation>Idź do wiersza</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Wiersz</translation>
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
        <source>Line</source>
        <translation>Wiersz</translation>
    </message>
    <message>
        <source>No messages</source>
        <translation>Brak komunikatów</translation>
    </message>
    <message>
        <source>line %1: </source>
        <translation>wiersz %1: </translation>
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
</context>
</TS>
