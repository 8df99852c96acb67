<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_PT">
<context>
    <name>kerf::ui::FileManager</name>
    <message>
        <source>All files</source>
        <translation>Todos os ficheiros</translation>
    </message>
    <message>
        <source>Programs (.H .I .PIT)</source>
        <translation>Programas (.H .I .PIT)</translation>
    </message>
    <message>
        <source>Tables (.T .TCH .PR .D .PNT .TAB)</source>
        <translation>Tabelas (.T .TCH .PR .D .PNT .TAB)</translation>
    </message>
    <message>
        <source>NC root: %1</source>
        <translation>Raiz NC: %1</translation>
    </message>
    <message>
        <source>Recent files</source>
        <translation>Ficheiros recentes</translation>
    </message>
    <message>
        <source>File manager</source>
        <translation>Gestão de ficheiros</translation>
    </message>
    <message>
        <source>Copy %1 to:</source>
        <translation>Copiar %1 para:</translation>
    </message>
    <message>
        <source>Copied to %1</source>
        <translation>Copiado para %1</translation>
    </message>
    <message>
        <source>Move %1 to folder:</source>
        <translation>Mover %1 para a pasta:</translation>
    </message>
    <message>
        <source>New name for %1:</source>
        <translation>Novo nome para %1:</translation>
    </message>
    <message>
        <source>Delete %1?</source>
        <translation>Apagar %1?</translation>
    </message>
    <message>
        <source>Name of the new folder:</source>
        <translation>Nome da nova pasta:</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FindBar</name>
    <message>
        <source>Find</source>
        <translation>Procurar</translation>
    </message>
    <message>
        <source>Replace with</source>
        <translation>Substituir por</translation>
    </message>
    <message>
        <source>Match case</source>
        <translation>Maiúsculas/minúsculas</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>Anterior</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Seguinte</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Substituir</translation>
    </message>
    <message>
        <source>Replace all</source>
        <translation>Substituir tudo</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Fechar</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Não encontrado</translation>
    </message>
    <message numerus="yes">
        <source>%n replaced</source>
        <translation>
            <numerusform>%n substituição</numerusform>
            <numerusform>%n substituições</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>kerf::ui::MainWindow</name>
    <message>
        <source>Programming station</source>
        <translation>Posto de programação</translation>
    </message>
    <message>
        <source>%1 has unsaved changes from an earlier session: press &quot;Restore autosave&quot; to get them back</source>
        <translation>%1 tem alterações não guardadas de uma sessão anterior: prima &quot;Repor cópia automática&quot; para as recuperar</translation>
    </message>
    <message>
        <source>Kerf - %1</source>
        <translation>Kerf - %1</translation>
    </message>
    <message>
        <source>Graphics</source>
        <translation>Gráfico</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Positions: %1</source>
        <translation>Posições: %1</translation>
    </message>
    <message>
        <source>Screen
layout</source>
        <translation>Divisão
do ecrã</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Ficheiros</translation>
    </message>
    <message>
        <source>Tool
table</source>
        <translation>Tabela de
ferramentas</translation>
    </message>
    <message>
        <source>Preset
table</source>
        <translation>Tabela de
pontos de ref.</translation>
    </message>
    <message>
        <source>Message
list</source>
        <translation>Lista de
mensagens</translation>
    </message>
    <message>
        <source>Clear
messages</source>
        <translation>Apagar
mensagens</translation>
    </message>
    <message>
        <source>Language
%1</source>
        <translation>Idioma
%1</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Abrir</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Copiar</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Mover</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Mudar
nome</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Apagar</translation>
    </message>
    <message>
        <source>Protect /
unprotect</source>
        <translation>Proteger /
desproteger</translation>
    </message>
    <message>
        <source>New
folder</source>
        <translation>Nova
pasta</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Voltar</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Guardar</translation>
    </message>
    <message>
        <source>Insert
row</source>
        <translation>Inserir
linha</translation>
    </message>
    <message>
        <source>Delete
row</source>
        <translation>Apagar
linha</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Anular</translation>
    </message>
    <message>
        <source>Find /
replace</source>
        <translation>Procurar /
substituir</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Refazer</translation>
    </message>
    <message>
        <source>Go to
line</source>
        <translation>Ir para
linha</translation>
    </message>
    <message>
        <source>Go to line</source>
        <translation>Ir para linha</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Linha</translation>
    </message>
    <message>
        <source>Renumber
blocks</source>
        <translation>Renumerar
blocos</translation>
    </message>
    <message>
        <source>Check
program</source>
        <translation>Verificar
programa</translation>
    </message>
    <message>
        <source>Restore
autosave</source>
        <translation>Repor cópia
automática</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MessagePanel</name>
    <message>
        <source>Severity</source>
        <translation>Gravidade</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Mensagem</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Linha</translation>
    </message>
    <message>
        <source>No messages</source>
        <translation>Sem mensagens</translation>
    </message>
    <message>
        <source>line %1: </source>
        <translation>linha %1: </translation>
    </message>
    <message>
        <source>%1 - %2%3</source>
        <translation>%1 - %2%3</translation>
    </message>
    <message numerus="yes">
        <source> (%n more)</source>
        <translation>
            <numerusform> (mais %n)</numerusform>
            <numerusform> (mais %n)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>kerf::ui::ProgramPanel</name>
    <message>
        <source>Saved %1</source>
        <translation>%1 guardado</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>A cópia automática falhou: %1</translation>
    </message>
    <message>
        <source>No program</source>
        <translation>Nenhum programa</translation>
    </message>
    <message>
        <source>Loading %1 ...</source>
        <translation>A carregar %1 ...</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TableEditor</name>
    <message>
        <source>No table</source>
        <translation>Nenhuma tabela</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>Procurar</translation>
    </message>
    <message>
        <source>Not saved: correct the table first</source>
        <translation>Não guardado: corrija primeiro a tabela</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 guardado</translation>
    </message>
    <message>
        <source>Delete row %1 (%2)?</source>
        <translation>Apagar a linha %1 (%2)?</translation>
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
        <translation>Programa</translation>
    </message>
    <message>
        <source>Program +
graphics</source>
        <translation>Programa +
gráfico</translation>
    </message>
    <message>
        <source>Program +
status</source>
        <translation>Programa +
estado</translation>
    </message>
    <message>
        <source>Positions +
status</source>
        <translation>Posições +
estado</translation>
    </message>
</context>
<context>
    <name>kerf</name>
    <message>
        <source>programming station: no machine is connected, only Programming and Test run are available</source>
        <translation>posto de programação: nenhuma máquina ligada, só estão disponíveis Programação e Teste do programa</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Aviso</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Erro</translation>
    </message>
    <message>
        <source>Manual operation</source>
        <translation>Funcionamento manual</translation>
    </message>
    <message>
        <source>Electronic handwheel</source>
        <translation>Volante electrónico</translation>
    </message>
    <message>
        <source>Positioning with manual data input</source>
        <translation>Posicionamento com introdução manual</translation>
    </message>
    <message>
        <source>Program run, single block</source>
        <translation>Execução do programa, bloco a bloco</translation>
    </message>
    <message>
        <source>Program run, full sequence</source>
        <translation>Execução contínua do programa</translation>
    </message>
    <message>
        <source>Programming</source>
        <translation>Programação</translation>
    </message>
    <message>
        <source>Test run</source>
        <translation>Teste do programa</translation>
    </message>
    <message>
        <source>stop the program before changing the operating mode</source>
        <translation>pare o programa antes de mudar o modo de funcionamento</translation>
    </message>
</context>
</TS>
