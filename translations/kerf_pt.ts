<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_PT">
<context>
    <name>kerf::ui::CycleCatalogueDialog</name>
    <message>
        <source>There is no cycle %1</source>
        <translation>Não existe o ciclo %1</translation>
    </message>
    <message>
        <source>Cycle definition</source>
        <translation>Definição de ciclo</translation>
    </message>
    <message>
        <source>Cycle number</source>
        <translation>Número de ciclo</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::CycleDialog</name>
    <message>
        <source>Cycle definition</source>
        <translation>Definição de ciclo</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FagorCycleDialog</name>
    <message>
        <source>Canned cycle</source>
        <translation>Ciclo fixo</translation>
    </message>
    <message>
        <source>* required</source>
        <translation>* obrigatório</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::FagorTableModel</name>
    <message>
        <source>Key</source>
        <translation>Chave</translation>
    </message>
</context>
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
    <message>
        <source>Tables (.T .TCH .PR .D .PNT .TP .TAB)</source>
        <translation>Tabelas (.T .TCH .PR .D .PNT .TP .TAB)</translation>
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
    <name>kerf::ui::FkSketchView</name>
    <message>
        <source>Contour</source>
        <translation>Contorno</translation>
    </message>
    <message>
        <source>FK element determined</source>
        <translation>Elemento FK determinado</translation>
    </message>
    <message>
        <source>FK element not determined</source>
        <translation>Elemento FK não determinado</translation>
    </message>
    <message>
        <source>Solution %1 of %2</source>
        <translation>Solução %1 de %2</translation>
    </message>
    <message>
        <source>Other solutions</source>
        <translation>Outras soluções</translation>
    </message>
    <message>
        <source>FK element with solution 1 assumed (no FSELECT)</source>
        <translation>Elemento FK com a solução 1 assumida (sem FSELECT)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::GraphicsPanel</name>
    <message>
        <source>The 3D graphics need a display</source>
        <translation>Os gráficos 3D precisam de um ecrã</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Velocidade</translation>
    </message>
    <message>
        <source>Machining time %1</source>
        <translation>Tempo de maquinagem %1</translation>
    </message>
    <message>
        <source>%1   %2 % done   %3 remaining</source>
        <translation>%1   %2 % concluído   faltam %3</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineKeys</name>
    <message>
        <source>Machine on</source>
        <translation>Máquina ligada</translation>
    </message>
    <message>
        <source>EMERGENCY STOP</source>
        <translation>PARADA DE EMERGÊNCIA</translation>
    </message>
    <message>
        <source>Release EMERGENCY STOP</source>
        <translation>Destravar PARADA DE EMERGÊNCIA</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineSession</name>
    <message>
        <source>The machine is busy: stop the program or wait until the axes stand still</source>
        <translation>A máquina está ocupada: pare o programa ou espere até os eixos pararem</translation>
    </message>
    <message>
        <source>The program has errors and cannot be started</source>
        <translation>O programa tem erros e não pode ser iniciado</translation>
    </message>
    <message>
        <source>Program finished</source>
        <translation>Programa terminado</translation>
    </message>
    <message>
        <source>Program stopped</source>
        <translation>Programa parado</translation>
    </message>
    <message>
        <source>The preset could not be saved in PRESET.PR, so the next program uses the table&apos;s preset again: %1</source>
        <translation>Não foi possível guardar o ponto de referência em PRESET.PR; o próximo programa volta a usar o ponto de referência da tabela: %1</translation>
    </message>
    <message>
        <source>The machine is off (emergency stop or drive fault): switch it on with Machine on</source>
        <translation>A máquina está desligada (parada de emergência ou falha de acionamento): ligue-a com Máquina ligada</translation>
    </message>
    <message>
        <source>The machine is on already</source>
        <translation>A máquina já está ligada</translation>
    </message>
    <message>
        <source>The axes are not referenced: run Home all in Manual operation first</source>
        <translation>Os eixos não estão referenciados: execute primeiro Referenciar todos em Funcionamento manual</translation>
    </message>
    <message>
        <source>The emergency stop button is pressed: release it, then Machine on</source>
        <translation>O botão de emergência está premido: destrave-o e depois Máquina ligada</translation>
    </message>
    <message>
        <source>Release the emergency stop button first</source>
        <translation>Destrave primeiro o botão de emergência</translation>
    </message>
    <message>
        <source>The emergency stop chain is still open</source>
        <translation>O circuito de emergência ainda está aberto</translation>
    </message>
    <message>
        <source>Probing: the stylus is deflected already</source>
        <translation>Apalpação: a haste já está desviada</translation>
    </message>
    <message>
        <source>Probing: no touch within %1 mm</source>
        <translation>Apalpação: nenhum contacto em %1 mm</translation>
    </message>
    <message>
        <source>The basic rotation could not be saved in PRESET.PR: %1</source>
        <translation>Não foi possível guardar a rotação básica em PRESET.PR: %1</translation>
    </message>
    <message>
        <source>The tool offset must be D1 to D255</source>
        <translation>O corretor da ferramenta deve ser D1 a D255</translation>
    </message>
    <message>
        <source>Tool calibration: %1</source>
        <translation>Calibração de ferramentas: %1</translation>
    </message>
    <message>
        <source>Tool calibration works on X and Z only</source>
        <translation>A calibração de ferramentas atua só em X e Z</translation>
    </message>
    <message>
        <source>Tool %1: L = %2 mm</source>
        <translation>Ferramenta %1: L = %2 mm</translation>
    </message>
    <message>
        <source>The probing log TCHPRMAN.html could not be written: %1</source>
        <translation>Não foi possível escrever o protocolo de apalpação TCHPRMAN.html: %1</translation>
    </message>
    <message>
        <source>Tool offset D%1: X = %2 mm (radius)</source>
        <translation>Corretor D%1: X = %2 mm (raio)</translation>
    </message>
    <message>
        <source>Tool offset D%1: Z = %2 mm</source>
        <translation>Corretor D%1: Z = %2 mm</translation>
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
    <message>
        <source>Tables</source>
        <translation>Tabelas</translation>
    </message>
    <message>
        <source>MOD</source>
        <translation>MOD</translation>
    </message>
    <message>
        <source>No program is open: open one in Files</source>
        <translation>Nenhum programa aberto: abra um em Ficheiros</translation>
    </message>
    <message>
        <source>Machine
parameters</source>
        <translation>Parâmetros
de máquina</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parar</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Repor</translation>
    </message>
    <message>
        <source>Speed
%1</source>
        <translation>Velocidade
%1</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Vista</translation>
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
        <translation>Novo
programa</translation>
    </message>
    <message>
        <source>Go to
block</source>
        <translation>Ir para
bloco</translation>
    </message>
    <message>
        <source>Go to block</source>
        <translation>Ir para bloco</translation>
    </message>
    <message>
        <source>The program</source>
        <translation>O programa</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Alterações não guardadas</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 tem alterações não guardadas. Guardá-las?</translation>
    </message>
    <message>
        <source>A program is running. Stop it and quit?</source>
        <translation>Um programa está em execução. Pará-lo e sair?</translation>
    </message>
    <message>
        <source>The spindle turns. Stop it and quit?</source>
        <translation>O mandril está a rodar. Pará-lo e sair?</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Sair</translation>
    </message>
    <message>
        <source>Start at block</source>
        <translation>Iniciar no bloco</translation>
    </message>
    <message>
        <source>No user customisation program: %1 is not in the NC root</source>
        <translation>Nenhum programa de personalização do usuário: %1 não está na raiz NC</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Usuário</translation>
    </message>
    <message>
        <source>Leave
user screen</source>
        <translation>Sair da
tela do usuário</translation>
    </message>
    <message>
        <source>The program in the editor is protected: the block %1 of the user screen was not inserted</source>
        <translation>O programa no editor está protegido: o bloco %1 da tela do usuário não foi inserido</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MdiDialog</name>
    <message>
        <source>Positioning with MDI</source>
        <translation>Posicionamento com MDI</translation>
    </message>
    <message>
        <source>Block (arrow keys: the blocks run before)</source>
        <translation>Bloco (teclas de seta: os blocos executados antes)</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
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
        <source>No messages</source>
        <translation>Sem mensagens</translation>
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
    <message>
        <source>Block</source>
        <translation>Bloco</translation>
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
        <translation>Funções MOD</translation>
    </message>
    <message>
        <source>Position display</source>
        <translation>Visualização de posição</translation>
    </message>
    <message>
        <source>Unit of the position display</source>
        <translation>Unidade da visualização de posição</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <source>Software: Kerf %1 (Qt %2)
Machine: %3</source>
        <translation>Software: Kerf %1 (Qt %2)
Máquina: %3</translation>
    </message>
    <message>
        <source>Kerf is free software: you may share and change it under the GNU General Public License, version 3 or later. It comes with no warranty.</source>
        <translation>O Kerf é software livre: pode redistribuí-lo e modificá-lo nos termos da Licença Pública Geral GNU, versão 3 ou posterior. É fornecido sem qualquer garantia.</translation>
    </message>
</context>
<context>
    <name>kerf::ui::NewProgramDialog</name>
    <message>
        <source>New program</source>
        <translation>Novo programa</translation>
    </message>
    <message>
        <source>Program name</source>
        <translation>Nome do programa</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unidade</translation>
    </message>
    <message>
        <source>Blank MIN %1</source>
        <translation>Peça bruta MIN %1</translation>
    </message>
    <message>
        <source>Blank MAX %1</source>
        <translation>Peça bruta MAX %1</translation>
    </message>
    <message>
        <source>Give the program a name without spaces or folders</source>
        <translation>Dê ao programa um nome sem espaços nem pastas</translation>
    </message>
    <message>
        <source>The blank&apos;s MIN point must lie below its MAX point on every axis</source>
        <translation>O ponto MIN da peça bruta tem de ficar abaixo do ponto MAX em todos os eixos</translation>
    </message>
</context>
<context>
    <name>kerf::ui::OperatorInputDialog</name>
    <message>
        <source>Operator inputs</source>
        <translation>Entradas do operador</translation>
    </message>
    <message>
        <source>The program reads these inputs: enter their values</source>
        <translation>O programa lê estas entradas: introduza os seus valores</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
</context>
<context>
    <name>kerf::ui::OverrideControls</name>
    <message>
        <source>Feed</source>
        <translation>Avanço</translation>
    </message>
    <message>
        <source>Rapid</source>
        <translation>Rápido</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Mandril</translation>
    </message>
</context>
<context>
    <name>kerf::ui::PathFunctionDialog</name>
    <message>
        <source>Path function</source>
        <translation>Função de trajetória</translation>
    </message>
</context>
<context>
    <name>kerf::ui::PositionDisplay</name>
    <message>
        <source>ACTL.</source>
        <translation>REAL</translation>
    </message>
    <message>
        <source>NOML.</source>
        <translation>NOM.</translation>
    </message>
    <message>
        <source>REF ACTL.</source>
        <translation>REF REAL</translation>
    </message>
    <message>
        <source>REF NOML.</source>
        <translation>REF NOM.</translation>
    </message>
    <message>
        <source>LAG</source>
        <translation>ERRO ARR.</translation>
    </message>
    <message>
        <source>DIST.</source>
        <translation>DIST.</translation>
    </message>
    <message>
        <source>Program: %1   Machine: %2</source>
        <translation>Programa: %1   Máquina: %2</translation>
    </message>
    <message>
        <source>T %1</source>
        <translation>T %1</translation>
    </message>
    <message>
        <source>F %1 (actual %2) %3</source>
        <translation>F %1 (real %2) %3</translation>
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
        <translation>S %1 (real %2) rpm</translation>
    </message>
    <message>
        <source>Not referenced: Home all in Manual operation</source>
        <translation>Não referenciado: Referenciar todos em Funcionamento manual</translation>
    </message>
    <message>
        <source>Coolant on</source>
        <translation>Refrigeração ligada</translation>
    </message>
    <message>
        <source>Coolant off</source>
        <translation>Refrigeração desligada</translation>
    </message>
    <message>
        <source>inch/rev</source>
        <translation>inch/rot</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/rot</translation>
    </message>
    <message>
        <source>S %1 ft/min (actual %2 rpm)</source>
        <translation>S %1 pés/min (real %2 rpm)</translation>
    </message>
    <message>
        <source>S %1 m/min (actual %2 rpm)</source>
        <translation>S %1 m/min (real %2 rpm)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::ProgramFileDialog</name>
    <message>
        <source>Select file</source>
        <translation>Selecionar ficheiro</translation>
    </message>
    <message>
        <source>NC root: %1</source>
        <translation>Raiz NC: %1</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Choose a program (.H or .I)</source>
        <translation>Escolha um programa (.H ou .I)</translation>
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
    <message>
        <source>Checking the program: it runs without moving the machine</source>
        <translation>A verificar o programa: é executado sem mover a máquina</translation>
    </message>
    <message>
        <source>Program check: no errors, the program runs to its end</source>
        <translation>Verificação do programa: sem erros, o programa é executado até ao fim</translation>
    </message>
    <message>
        <source>Program check: the program cannot run (errors: %1)</source>
        <translation>Verificação do programa: o programa não pode ser executado (erros: %1)</translation>
    </message>
    <message>
        <source>%1 was not opened: %2 could not be saved</source>
        <translation>%1 não foi aberto: não foi possível guardar %2</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SettingsModel</name>
    <message>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation>Eixo %1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parâmetro</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unidade</translation>
    </message>
    <message>
        <source>Allowed</source>
        <translation>Permitido</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Por defeito</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Descrição</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SettingsPage</name>
    <message>
        <source>Not saved: correct the parameters first</source>
        <translation>Não guardado: corrija primeiro os parâmetros</translation>
    </message>
    <message>
        <source>Saved %1: the changes apply when Kerf is restarted</source>
        <translation>%1 guardado: as alterações aplicam-se quando o Kerf for reiniciado</translation>
    </message>
    <message>
        <source>Machine parameters</source>
        <translation>Parâmetros de máquina</translation>
    </message>
    <message>
        <source>Kerf reads the machine parameters when it starts: saved changes apply after a restart. This is a built-in machine: the parameters are saved to %1; start Kerf with --machine %1 to use them.</source>
        <translation>O Kerf lê os parâmetros de máquina ao arrancar: as alterações guardadas aplicam-se depois de reiniciar. Esta é uma máquina incorporada: os parâmetros são guardados em %1; inicie o Kerf com --machine %1 para os usar.</translation>
    </message>
    <message>
        <source>Kerf reads the machine parameters when it starts: saved changes to %1 apply after a restart.</source>
        <translation>O Kerf lê os parâmetros de máquina ao arrancar: as alterações guardadas em %1 aplicam-se depois de reiniciar.</translation>
    </message>
    <message>
        <source>Wrong code number: the machine parameters stay locked</source>
        <translation>Código numérico errado: os parâmetros da máquina continuam bloqueados</translation>
    </message>
    <message>
        <source>Machine parameters unlocked for editing</source>
        <translation>Parâmetros da máquina desbloqueados para edição</translation>
    </message>
    <message>
        <source>Code number for editing</source>
        <translation>Código numérico para editar</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Desbloquear</translation>
    </message>
</context>
<context>
    <name>kerf::ui::SpecialFunctionDialog</name>
    <message>
        <source>Special function</source>
        <translation>Função especial</translation>
    </message>
    <message>
        <source>Select file</source>
        <translation>Selecionar ficheiro</translation>
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
        <translation>Filtro, p. ex. %1</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programa</translation>
    </message>
    <message>
        <source>Called program</source>
        <translation>Programa chamado</translation>
    </message>
    <message>
        <source>Label</source>
        <translation>Label</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <source>M functions</source>
        <translation>Funções M</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unidade</translation>
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
        <translation>Ferramenta</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Corretor</translation>
    </message>
    <message>
        <source>X (radius)</source>
        <translation>X (raio)</translation>
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
        <translation>Desgaste X (I)</translation>
    </message>
    <message>
        <source>Wear Z (K)</source>
        <translation>Desgaste Z (K)</translation>
    </message>
    <message>
        <source>Location code (F)</source>
        <translation>Código de localização (F)</translation>
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
        <translation>Eixo da ferramenta</translation>
    </message>
    <message>
        <source>Zero offset</source>
        <translation>Origem</translation>
    </message>
    <message>
        <source>Datum shift %1</source>
        <translation>Deslocação do ponto zero %1</translation>
    </message>
    <message>
        <source>Mirrored axes</source>
        <translation>Eixos espelhados</translation>
    </message>
    <message>
        <source>Rotation</source>
        <translation>Rotação</translation>
    </message>
    <message>
        <source>Scaling</source>
        <translation>Fator de escala</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>global</source>
        <translation>global</translation>
    </message>
    <message>
        <source>local, level %1</source>
        <translation>local, nível %1</translation>
    </message>
    <message>
        <source>local</source>
        <translation>local</translation>
    </message>
    <message>
        <source>remanent</source>
        <translation>remanente</translation>
    </message>
    <message>
        <source>text</source>
        <translation>texto</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Apalpador</translation>
    </message>
    <message>
        <source>no result</source>
        <translation>sem resultado</translation>
    </message>
    <message>
        <source>touched</source>
        <translation>tocou</translation>
    </message>
    <message>
        <source>not touched</source>
        <translation>não tocou</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Mandril</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Avanço</translation>
    </message>
    <message>
        <source>S %1 %2 (constant surface speed)</source>
        <translation>S %1 %2 (velocidade de corte constante)</translation>
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
        <translation>S %1 rpm</translation>
    </message>
    <message>
        <source>limit %1 rpm</source>
        <translation>limite %1 rpm</translation>
    </message>
    <message>
        <source>in/rev</source>
        <translation>in/rot</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>mm/rot</translation>
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
        <translation>Bloco</translation>
    </message>
    <message>
        <source>Working plane</source>
        <translation>Plano de trabalho</translation>
    </message>
    <message>
        <source>Working plane %1</source>
        <translation>Plano de trabalho %1</translation>
    </message>
    <message>
        <source>Rotary axes</source>
        <translation>Eixos rotativos</translation>
    </message>
    <message>
        <source>Manual probing</source>
        <translation>Apalpação manual</translation>
    </message>
    <message>
        <source>Basic rotation</source>
        <translation>Rotação básica</translation>
    </message>
    <message>
        <source>Probed %1</source>
        <translation>Apalpado %1</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>Diâmetro</translation>
    </message>
    <message>
        <source>Plane A</source>
        <translation>Plano A</translation>
    </message>
    <message>
        <source>Plane B</source>
        <translation>Plano B</translation>
    </message>
    <message>
        <source>Tool length T%1</source>
        <translation>Comprimento da ferramenta T%1</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>follows when the program is prepared</source>
        <translation>segue quando o programa estiver preparado</translation>
    </message>
    <message>
        <source>none</source>
        <comment>cycle</comment>
        <translation>nenhum</translation>
    </message>
    <message>
        <source>none</source>
        <comment>program</comment>
        <translation>nenhum</translation>
    </message>
    <message>
        <source>none</source>
        <comment>called program</comment>
        <translation>nenhum</translation>
    </message>
    <message>
        <source>none</source>
        <comment>label</comment>
        <translation>nenhum</translation>
    </message>
    <message>
        <source>none</source>
        <comment>M functions</comment>
        <translation>nenhuma</translation>
    </message>
    <message>
        <source>none</source>
        <comment>tool</comment>
        <translation>nenhuma</translation>
    </message>
    <message>
        <source>none</source>
        <comment>mirrored axes</comment>
        <translation>nenhum</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TableChooser</name>
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
pontos ref.</translation>
    </message>
    <message>
        <source>Datum
table</source>
        <translation>Tabela de
pontos zero</translation>
    </message>
    <message>
        <source>Point
table</source>
        <translation>Tabela de
pontos</translation>
    </message>
    <message>
        <source>Touch probe
table</source>
        <translation>Tabela de
apalpadores</translation>
    </message>
    <message>
        <source>Tool
offsets</source>
        <translation>Corretores
ferramenta</translation>
    </message>
    <message>
        <source>Zero
offsets</source>
        <translation>Origens</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Tabela</translation>
    </message>
    <message>
        <source>Lengths, radii, wear and life of the tools</source>
        <translation>Comprimentos, raios, desgaste e vida útil das ferramentas</translation>
    </message>
    <message>
        <source>Reference points of the workpieces, in machine coordinates</source>
        <translation>Pontos de referência das peças, em coordenadas de máquina</translation>
    </message>
    <message>
        <source>Zero offsets relative to the active preset (CYCL DEF 7)</source>
        <translation>Pontos zero relativos ao ponto de referência ativo (CYCL DEF 7)</translation>
    </message>
    <message>
        <source>Machining positions for patterns (SEL PATTERN)</source>
        <translation>Posições de maquinagem para padrões (SEL PATTERN)</translation>
    </message>
    <message>
        <source>Workpiece touch probes: centre offset, feeds, probing path</source>
        <translation>Apalpadores de peça: desvio do centro, avanços, percurso de apalpação</translation>
    </message>
    <message>
        <source>Tool offsets D: X, Z, nose radius R, location code F, wear I, K</source>
        <translation>Corretores de ferramenta D: X, Z, raio da ponta R, código de localização F, desgaste I, K</translation>
    </message>
    <message>
        <source>Zero offsets G54-G59, G159 N7-N20 and the PLC offset, from machine zero</source>
        <translation>Origens G54-G59, G159 N7-N20 e a origem do PLC, a partir do zero máquina</translation>
    </message>
    <message>
        <source>Tools T: offset D, family, tool life, nose angle and width</source>
        <translation>Ferramentas T: corretor D, família, vida útil, ângulo e largura da ponta</translation>
    </message>
    <message>
        <source>Tables</source>
        <translation>Tabelas</translation>
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
    <message>
        <source>%1 was changed on disk (e.g. by a tool measurement): reloaded</source>
        <translation>%1 foi alterada no disco (p. ex. por uma medição de ferramenta): recarregada</translation>
    </message>
    <message>
        <source>%1 was changed on disk while you edit it: saving would overwrite those changes</source>
        <translation>%1 foi alterada no disco enquanto a edita: guardar substituiria essas alterações</translation>
    </message>
    <message>
        <source>%1 was changed on disk since it was opened here (e.g. by a tool measurement). Overwrite it with the table shown?</source>
        <translation>%1 foi alterada no disco desde que foi aberta aqui (p. ex. por uma medição de ferramenta). Substituí-la pela tabela mostrada?</translation>
    </message>
    <message>
        <source>Not saved: the file on disk is kept</source>
        <translation>Não guardado: mantém-se o ficheiro do disco</translation>
    </message>
</context>
<context>
    <name>kerf::ui::TestRunController</name>
    <message>
        <source>max</source>
        <translation>máx</translation>
    </message>
    <message>
        <source>Test run: %1</source>
        <translation>Teste do programa: %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::UserScreenView</name>
    <message>
        <source>User screen</source>
        <translation>Tela do usuário</translation>
    </message>
    <message>
        <source>User screen - page %1</source>
        <translation>Tela do usuário - página %1</translation>
    </message>
    <message>
        <source>Enter IB%1 (format %2%3.%4) and press Enter</source>
        <translation>Introduza IB%1 (formato %2%3.%4) e pressione Enter</translation>
    </message>
    <message>
        <source>Waiting for a key: press a softkey</source>
        <translation>Esperando uma tecla: pressione uma softkey</translation>
    </message>
    <message>
        <source>The customisation program has ended</source>
        <translation>O programa de personalização terminou</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Em execução</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Parado</translation>
    </message>
    <message>
        <source>Block being edited: %1</source>
        <translation>Bloco em edição: %1</translation>
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
        <translation>Planta</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Frente</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Lado</translation>
    </message>
    <message>
        <source>Section</source>
        <translation>Corte</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Ajustar</translation>
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
        <translation>Cancelar</translation>
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
        <translation>Volante eletrónico</translation>
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
    <message>
        <source>cannot {1}: {2}</source>
        <translation>não é possível {1}: {2}</translation>
    </message>
    <message>
        <source>Set-up clearance: tool tip to workpiece surface</source>
        <translation>Distância de segurança: extremidade da ferramenta à superfície da peça</translation>
    </message>
    <message>
        <source>Depth: workpiece surface to bottom (sign = direction)</source>
        <translation>Profundidade: superfície da peça ao fundo (sinal = direção)</translation>
    </message>
    <message>
        <source>Thread depth: workpiece surface to thread end</source>
        <translation>Profundidade da rosca: superfície da peça ao fim da rosca</translation>
    </message>
    <message>
        <source>Plunging depth per infeed</source>
        <translation>Profundidade de passo por corte</translation>
    </message>
    <message>
        <source>Workpiece surface coordinate</source>
        <translation>Coordenada da superfície da peça</translation>
    </message>
    <message>
        <source>2nd set-up clearance: no collision above this height</source>
        <translation>2.ª distância de segurança: sem colisão acima desta altura</translation>
    </message>
    <message>
        <source>Minimum plunging depth when decreasing</source>
        <translation>Profundidade de passo mínima ao reduzir</translation>
    </message>
    <message>
        <source>Feed rate for plunging</source>
        <translation>Avanço de incremento em profundidade</translation>
    </message>
    <message>
        <source>Feed rate for milling</source>
        <translation>Avanço de fresagem</translation>
    </message>
    <message>
        <source>Retraction feed rate (0: plunging feed)</source>
        <translation>Avanço de retrocesso (0: avanço de incremento)</translation>
    </message>
    <message>
        <source>Dwell time at the top</source>
        <translation>Tempo de espera em cima</translation>
    </message>
    <message>
        <source>Dwell time at depth</source>
        <translation>Tempo de espera em baixo</translation>
    </message>
    <message>
        <source>Decrement of the plunging depth after each infeed</source>
        <translation>Redução da profundidade de passo após cada corte</translation>
    </message>
    <message>
        <source>Feed rate for pre-positioning</source>
        <translation>Avanço de posicionamento prévio</translation>
    </message>
    <message>
        <source>Feed rate for countersinking</source>
        <translation>Avanço de rebaixamento</translation>
    </message>
    <message>
        <source>Retraction distance for chip breaking</source>
        <translation>Distância de retrocesso na rotura de apara</translation>
    </message>
    <message>
        <source>Depth for chip breaking (0: none)</source>
        <translation>Profundidade para rotura de apara (0: nenhuma)</translation>
    </message>
    <message>
        <source>Upper advanced stop distance</source>
        <translation>Distância de paragem prévia superior</translation>
    </message>
    <message>
        <source>Angle for spindle orientation</source>
        <translation>Ângulo para a orientação do mandril</translation>
    </message>
    <message>
        <source>Disengaging direction (0 none, 1 -main, 2 -secondary, 3 +main, 4 +secondary axis)</source>
        <translation>Direção de afastamento (0 nenhuma, 1 -eixo principal, 2 -eixo secundário, 3 +eixo principal, 4 +eixo secundário)</translation>
    </message>
    <message>
        <source>Nominal diameter</source>
        <translation>Diâmetro nominal</translation>
    </message>
    <message>
        <source>Thread pitch (+ right-hand, - left-hand)</source>
        <translation>Passo de rosca (+ rosca direita, - rosca esquerda)</translation>
    </message>
    <message>
        <source>Climb (+1) or up-cut (-1) milling with M3</source>
        <translation>Fresagem sincronizada (+1) ou em contramarcha (-1) com M3</translation>
    </message>
    <message>
        <source>Threads per step (0 one 360° helix, 1 continuous)</source>
        <translation>Passos de rosca por passo (0 uma hélice de 360°, 1 contínuo)</translation>
    </message>
    <message>
        <source>Countersinking depth: surface to tool tip</source>
        <translation>Profundidade de rebaixamento: superfície à extremidade da ferramenta</translation>
    </message>
    <message>
        <source>Total hole depth</source>
        <translation>Profundidade total do furo</translation>
    </message>
    <message>
        <source>Clearance to side: tool edge to hole wall</source>
        <translation>Distância lateral: aresta da ferramenta à parede do furo</translation>
    </message>
    <message>
        <source>Depth at front: surface to tool tip</source>
        <translation>Profundidade frontal: superfície à extremidade da ferramenta</translation>
    </message>
    <message>
        <source>Countersinking offset at front (tool centre)</source>
        <translation>Desvio de rebaixamento frontal (centro da ferramenta)</translation>
    </message>
    <message>
        <source>Feed rate for approaching (0: milling feed)</source>
        <translation>Avanço de aproximação (0: avanço de fresagem)</translation>
    </message>
    <message>
        <source>Deepened starting point below the surface</source>
        <translation>Ponto inicial aprofundado abaixo da superfície</translation>
    </message>
    <message>
        <source>Depth reference (0 tool tip, 1 cylindrical part)</source>
        <translation>Referência da profundidade (0 extremidade da ferramenta, 1 parte cilíndrica)</translation>
    </message>
    <message>
        <source>cycle {1}: {2} ({3}) = {4} must be a whole number from {5} to {6}</source>
        <translation>ciclo {1}: {2} ({3}) = {4} tem de ser um número inteiro de {5} a {6}</translation>
    </message>
    <message>
        <source>cycle {1}: {2} ({3}) = {4} is outside {5} to {6}</source>
        <translation>ciclo {1}: {2} ({3}) = {4} está fora de {5} a {6}</translation>
    </message>
    <message>
        <source>DRILLING</source>
        <translation>FURAR</translation>
    </message>
    <message>
        <source>REAMING</source>
        <translation>ALARGAR FURO</translation>
    </message>
    <message>
        <source>BORING</source>
        <translation>MANDRILAR</translation>
    </message>
    <message>
        <source>Number of chip breaks before retracting</source>
        <translation>Número de roturas de apara antes de retroceder</translation>
    </message>
    <message>
        <source>UNIVERSAL DRILLING</source>
        <translation>FURAR UNIVERSAL</translation>
    </message>
    <message>
        <source>Depth of counterbore from the underside (+ upwards)</source>
        <translation>Profundidade do rebaixamento a partir da face inferior (+ para cima)</translation>
    </message>
    <message>
        <source>Material thickness</source>
        <translation>Espessura do material</translation>
    </message>
    <message>
        <source>Off-centre distance of the boring bar</source>
        <translation>Distância excêntrica da barra de mandrilar</translation>
    </message>
    <message>
        <source>Tool edge height above the underside of the bar</source>
        <translation>Altura da aresta da ferramenta acima da face inferior da barra</translation>
    </message>
    <message>
        <source>Feed rate for counterboring</source>
        <translation>Avanço de rebaixamento</translation>
    </message>
    <message>
        <source>Dwell time at the counterbore floor</source>
        <translation>Tempo de espera no fundo do rebaixamento</translation>
    </message>
    <message>
        <source>Disengaging direction (1 -main, 2 -secondary, 3 +main, 4 +secondary axis)</source>
        <translation>Direção de afastamento (1 -eixo principal, 2 -eixo secundário, 3 +eixo principal, 4 +eixo secundário)</translation>
    </message>
    <message>
        <source>BACK BORING</source>
        <translation>REBAIXAMENTO INVERTIDO</translation>
    </message>
    <message>
        <source>Lower advanced stop distance</source>
        <translation>Distância de paragem prévia inferior</translation>
    </message>
    <message>
        <source>cycle {1}: the starting point Q379 lies at or below the depth</source>
        <translation>ciclo {1}: o ponto inicial Q379 está à altura da profundidade ou abaixo dela</translation>
    </message>
    <message>
        <source>UNIVERSAL PECKING</source>
        <translation>FURAR EM PROFUNDIDADE UNIVERSAL</translation>
    </message>
    <message>
        <source>Feed rate for helical drilling</source>
        <translation>Avanço de furação helicoidal</translation>
    </message>
    <message>
        <source>Infeed per helix revolution</source>
        <translation>Passo por rotação da hélice</translation>
    </message>
    <message>
        <source>Roughing (pre-drilled) diameter</source>
        <translation>Diâmetro de desbaste (pré-furado)</translation>
    </message>
    <message>
        <source>cycle {1}: the nominal diameter {2} is smaller than the tool diameter {3}</source>
        <translation>ciclo {1}: o diâmetro nominal {2} é menor que o diâmetro da ferramenta {3}</translation>
    </message>
    <message>
        <source>cycle {1}: the nominal diameter is more than twice the tool diameter; enter the roughing diameter Q342</source>
        <translation>ciclo {1}: o diâmetro nominal é mais do dobro do diâmetro da ferramenta; introduza o diâmetro de desbaste Q342</translation>
    </message>
    <message>
        <source>cycle {1}: the infeed per helix Q334 must be greater than 0</source>
        <translation>ciclo {1}: o passo por hélice Q334 tem de ser maior que 0</translation>
    </message>
    <message>
        <source>BORE MILLING</source>
        <translation>FRESAR FURO</translation>
    </message>
    <message>
        <source>Select depth (0) or diameter (1)</source>
        <translation>Selecionar profundidade (0) ou diâmetro (1)</translation>
    </message>
    <message>
        <source>Countersink diameter (sign = direction)</source>
        <translation>Diâmetro de rebaixamento (sinal = direção)</translation>
    </message>
    <message>
        <source>CENTERING</source>
        <translation>CENTRAR</translation>
    </message>
    <message>
        <source>Direction of rotation for entry and exit (3 M3, 4 M4, 5 stationary)</source>
        <translation>Sentido de rotação na entrada e na saída (3 M3, 4 M4, 5 parado)</translation>
    </message>
    <message>
        <source>Spindle speed for entry and exit</source>
        <translation>Velocidade do mandril na entrada e na saída</translation>
    </message>
    <message>
        <source>Spindle speed for drilling</source>
        <translation>Velocidade do mandril ao furar</translation>
    </message>
    <message>
        <source>M function for coolant on (0: none)</source>
        <translation>Função M para ligar o refrigerante (0: nenhuma)</translation>
    </message>
    <message>
        <source>M function for coolant off (0: none)</source>
        <translation>Função M para desligar o refrigerante (0: nenhuma)</translation>
    </message>
    <message>
        <source>Dwell depth where the feed reduction begins (0: none)</source>
        <translation>Profundidade de espera onde começa a redução do avanço (0: nenhuma)</translation>
    </message>
    <message>
        <source>Feed rate factor beyond the dwell depth</source>
        <translation>Fator de avanço além da profundidade de espera</translation>
    </message>
    <message>
        <source>Maximum plunging depth</source>
        <translation>Profundidade de passo máxima</translation>
    </message>
    <message>
        <source>SINGLE-LIP DEEP-HOLE DRILLING</source>
        <translation>FURAR EM PROFUNDIDADE COM UM SÓ GUME</translation>
    </message>
    <message>
        <source>cycle {1}: the depth Q{2} = {3} is positive (the machine parameter displayDepthErr forbids it)</source>
        <translation>ciclo {1}: a profundidade Q{2} = {3} é positiva (o parâmetro de máquina displayDepthErr proíbe-o)</translation>
    </message>
    <message>
        <source>cycle {1}: more than {2} infeeds; increase the plunging depth</source>
        <translation>ciclo {1}: mais de {2} passos; aumente a profundidade de passo</translation>
    </message>
    <message>
        <source>cycle {1} needs the point angle T-ANGLE of the tool in the tool table</source>
        <translation>o ciclo {1} precisa do ângulo da ponta T-ANGLE da ferramenta na tabela de ferramentas</translation>
    </message>
    <message>
        <source>cycle {1} needs more than {2} moves</source>
        <translation>o ciclo {1} precisa de mais de {2} movimentos</translation>
    </message>
    <message>
        <source>Path overlap factor</source>
        <translation>Fator de sobreposição de trajetória</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 helical, 2 reciprocating)</source>
        <translation>Estratégia de afundamento (0 vertical, 1 helicoidal, 2 pendular)</translation>
    </message>
    <message>
        <source>Set-up clearance</source>
        <translation>Distância de segurança</translation>
    </message>
    <message>
        <source>Clearance height (absolute)</source>
        <translation>Altura segura (absoluta)</translation>
    </message>
    <message>
        <source>Direction of rotation (+1 climb, -1 up-cut)</source>
        <translation>Sentido de rotação (+1 sincronizado, -1 contramarcha)</translation>
    </message>
    <message>
        <source>Set-up clearance of the probe</source>
        <translation>Distância de segurança do apalpador</translation>
    </message>
    <message>
        <source>Clearance height</source>
        <translation>Altura segura</translation>
    </message>
    <message>
        <source>Move to clearance height between points</source>
        <translation>Deslocar à altura segura entre pontos</translation>
    </message>
    <message>
        <source>Height between pattern points: 2nd set-up clearance (1) or the position at the start (0)</source>
        <translation>Altura entre os pontos do padrão: 2.ª distância de segurança (1) ou a posição no início (0)</translation>
    </message>
    <message>
        <source>GENERAL</source>
        <translation>GERAL</translation>
    </message>
    <message>
        <source>POCKET MILLING</source>
        <translation>FRESAR CAIXA</translation>
    </message>
    <message>
        <source>CONTOUR MILLING</source>
        <translation>FRESAR CONTORNO</translation>
    </message>
    <message>
        <source>PROBING</source>
        <translation>APALPAÇÃO</translation>
    </message>
    <message>
        <source>POSITIONING</source>
        <translation>POSICIONAMENTO</translation>
    </message>
    <message>
        <source>Centre in the 1st axis</source>
        <translation>Centro no 1.º eixo</translation>
    </message>
    <message>
        <source>Centre in the 2nd axis</source>
        <translation>Centro no 2.º eixo</translation>
    </message>
    <message>
        <source>Pitch circle diameter</source>
        <translation>Diâmetro do círculo teórico</translation>
    </message>
    <message>
        <source>Starting angle</source>
        <translation>Ângulo inicial</translation>
    </message>
    <message>
        <source>Stopping angle</source>
        <translation>Ângulo final</translation>
    </message>
    <message>
        <source>Stepping angle (0: from start, stop and count)</source>
        <translation>Incremento angular (0: a partir do início, do fim e do número)</translation>
    </message>
    <message>
        <source>Number of operations</source>
        <translation>Número de maquinagens</translation>
    </message>
    <message>
        <source>Move between operations at set-up clearance (0) or at the 2nd set-up clearance (1)</source>
        <translation>Deslocação entre maquinagens à distância de segurança (0) ou à 2.ª distância de segurança (1)</translation>
    </message>
    <message>
        <source>Type of traverse: straight line (0) or arc on the pitch circle (1)</source>
        <translation>Tipo de deslocação: reta (0) ou arco no círculo teórico (1)</translation>
    </message>
    <message>
        <source>cycle {1}: the stopping angle Q246 must differ from the starting angle Q245</source>
        <translation>ciclo {1}: o ângulo final Q246 tem de ser diferente do ângulo inicial Q245</translation>
    </message>
    <message>
        <source>POLAR PATTERN</source>
        <translation>PADRÃO DE PONTOS SOBRE CÍRCULO</translation>
    </message>
    <message>
        <source>Starting point in the 1st axis</source>
        <translation>Ponto inicial no 1.º eixo</translation>
    </message>
    <message>
        <source>Starting point in the 2nd axis</source>
        <translation>Ponto inicial no 2.º eixo</translation>
    </message>
    <message>
        <source>Spacing in the 1st axis</source>
        <translation>Distância no 1.º eixo</translation>
    </message>
    <message>
        <source>Spacing in the 2nd axis</source>
        <translation>Distância no 2.º eixo</translation>
    </message>
    <message>
        <source>Number of columns</source>
        <translation>Número de colunas</translation>
    </message>
    <message>
        <source>Number of lines</source>
        <translation>Número de linhas</translation>
    </message>
    <message>
        <source>Angle of rotation about the starting point</source>
        <translation>Ângulo de rotação em torno do ponto inicial</translation>
    </message>
    <message>
        <source>cycle {1}: more than {2} positions</source>
        <translation>ciclo {1}: mais de {2} posições</translation>
    </message>
    <message>
        <source>CARTESIAN PATTERN</source>
        <translation>PADRÃO DE PONTOS SOBRE LINHAS</translation>
    </message>
    <message>
        <source>PATTERN DEF: {1} must be a whole number from 1 to 99999</source>
        <translation>PATTERN DEF: {1} tem de ser um número inteiro de 1 a 99999</translation>
    </message>
    <message>
        <source>PATTERN DEF: more than {1} positions</source>
        <translation>PATTERN DEF: mais de {1} posições</translation>
    </message>
    <message>
        <source>Engraving text</source>
        <translation>Texto a gravar</translation>
    </message>
    <message>
        <source>Character height (0: scaled to the text length Q574)</source>
        <translation>Altura dos caracteres (0: ajustada ao comprimento do texto Q574)</translation>
    </message>
    <message>
        <source>Spacing factor between the characters (0: as the font)</source>
        <translation>Fator de distância entre os caracteres (0: conforme a fonte)</translation>
    </message>
    <message>
        <source>Font (without function)</source>
        <translation>Fonte (sem função)</translation>
    </message>
    <message>
        <source>Text on a line (0), an arc (1) or an arc, continuous (2)</source>
        <translation>Texto numa reta (0), num arco (1) ou num arco, contínuo (2)</translation>
    </message>
    <message>
        <source>Angle of rotation (centre angle on an arc)</source>
        <translation>Ângulo de rotação (ângulo central num arco)</translation>
    </message>
    <message>
        <source>Radius of the arc the text is on</source>
        <translation>Raio do arco onde está o texto</translation>
    </message>
    <message>
        <source>Reference of the text position (0-6)</source>
        <translation>Referência da posição do texto (0-6)</translation>
    </message>
    <message>
        <source>Maximum text length (0: no limit)</source>
        <translation>Comprimento máximo do texto (0: sem limite)</translation>
    </message>
    <message>
        <source>ENGRAVING</source>
        <translation>GRAVAR</translation>
    </message>
    <message>
        <source>Strategy (0 meander outside, 1 meander on the edge, 2 line by line)</source>
        <translation>Estratégia (0 meandro por fora, 1 meandro na aresta, 2 linha a linha)</translation>
    </message>
    <message>
        <source>Starting point in the 3rd axis (surface)</source>
        <translation>Ponto inicial no 3.º eixo (superfície)</translation>
    </message>
    <message>
        <source>End point in the 3rd axis</source>
        <translation>Ponto final no 3.º eixo</translation>
    </message>
    <message>
        <source>First side length (sign = direction)</source>
        <translation>Comprimento do 1.º lado (sinal = direção)</translation>
    </message>
    <message>
        <source>Second side length (sign = direction)</source>
        <translation>Comprimento do 2.º lado (sinal = direção)</translation>
    </message>
    <message>
        <source>Finishing allowance for the floor</source>
        <translation>Sobre-medida de acabamento em profundidade</translation>
    </message>
    <message>
        <source>Maximum path overlap factor</source>
        <translation>Fator de sobreposição de trajetória máximo</translation>
    </message>
    <message>
        <source>Feed rate for finishing</source>
        <translation>Avanço de acabamento</translation>
    </message>
    <message>
        <source>Lateral clearance to the workpiece</source>
        <translation>Distância lateral à peça</translation>
    </message>
    <message>
        <source>cycle {1}: the starting point Q227 must be above the end point Q386</source>
        <translation>ciclo {1}: o ponto inicial Q227 tem de estar acima do ponto final Q386</translation>
    </message>
    <message>
        <source>cycle {1} needs a tool radius R greater than R2</source>
        <translation>o ciclo {1} precisa de um raio de ferramenta R maior que R2</translation>
    </message>
    <message>
        <source>FACE MILLING</source>
        <translation>FACEJAR</translation>
    </message>
    <message>
        <source>cycle 225: with the character height Q513 = 0 the text length Q574 must be given</source>
        <translation>ciclo 225: com a altura dos caracteres Q513 = 0 tem de ser indicado o comprimento do texto Q574</translation>
    </message>
    <message>
        <source>cycle 225: the text has no length that Q574 could scale</source>
        <translation>ciclo 225: o texto não tem comprimento que Q574 possa escalar</translation>
    </message>
    <message>
        <source>cycle 225: the text is {1} mm long, longer than the maximum text length Q574 = {2}</source>
        <translation>ciclo 225: o texto tem {1} mm de comprimento, mais do que o comprimento máximo Q574 = {2}</translation>
    </message>
    <message>
        <source>cycle 225: text on a circle needs the radius Q517</source>
        <translation>ciclo 225: texto num círculo precisa do raio Q517</translation>
    </message>
    <message>
        <source>cycle 225: the character &apos;{1}&apos; cannot be engraved</source>
        <translation>ciclo 225: o carácter &apos;{1}&apos; não pode ser gravado</translation>
    </message>
    <message>
        <source>cycle 225: unknown formatting character &apos;\{1}&apos; in the text (write \\ for a backslash)</source>
        <translation>ciclo 225: carácter de formatação desconhecido &apos;\{1}&apos; no texto (escreva \\ para uma barra invertida)</translation>
    </message>
    <message>
        <source>cycle 225: &apos;%time{1}&apos; is not a date format (use %time00 to %time15)</source>
        <translation>ciclo 225: &apos;%time{1}&apos; não é um formato de data (use %time00 a %time15)</translation>
    </message>
    <message>
        <source>cycle 225: &apos;%count&apos; needs the number of digits (1 to 9)</source>
        <translation>ciclo 225: &apos;%count&apos; precisa do número de algarismos (1 a 9)</translation>
    </message>
    <message>
        <source>cycle 225: unknown escape &apos;%{1}&apos; in the text (write %% for a percent sign)</source>
        <translation>ciclo 225: escape desconhecido &apos;%{1}&apos; no texto (escreva %% para um sinal de percentagem)</translation>
    </message>
    <message>
        <source>Dwell time</source>
        <translation>Tempo de espera</translation>
    </message>
    <message>
        <source>Program to call as a machining cycle</source>
        <translation>Programa a chamar como ciclo de maquinagem</translation>
    </message>
    <message>
        <source>Orientation angle of the spindle</source>
        <translation>Ângulo de orientação do mandril</translation>
    </message>
    <message>
        <source>Tolerance (0: machine default)</source>
        <translation>Tolerância (0: valor da máquina)</translation>
    </message>
    <message>
        <source>Filter: finishing (0) or roughing (1)</source>
        <translation>Filtro: acabamento (0) ou desbaste (1)</translation>
    </message>
    <message>
        <source>Tolerance of rotary axes (0: machine default)</source>
        <translation>Tolerância dos eixos rotativos (0: valor da máquina)</translation>
    </message>
    <message>
        <source>DWELL TIME</source>
        <translation>TEMPO DE ESPERA</translation>
    </message>
    <message>
        <source>PGM CALL</source>
        <translation>PGM CALL</translation>
    </message>
    <message>
        <source>ORIENTED SPINDLE STOP</source>
        <translation>ORIENTAÇÃO DO MANDRIL</translation>
    </message>
    <message>
        <source>TOLERANCE</source>
        <translation>TOLERÂNCIA</translation>
    </message>
    <message>
        <source>Total hole depth from the current position</source>
        <translation>Profundidade total do furo a partir da posição atual</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch is 0</source>
        <translation>ciclo {1}: o passo de rosca é 0</translation>
    </message>
    <message>
        <source>THREAD CUTTING</source>
        <translation>ROSCAGEM</translation>
    </message>
    <message>
        <source>Feed rate for tapping (spindle speed x pitch)</source>
        <translation>Avanço de roscagem (velocidade do mandril x passo)</translation>
    </message>
    <message>
        <source>cycle {1} needs the spindle running (M3 or M4)</source>
        <translation>o ciclo {1} precisa do mandril a rodar (M3 ou M4)</translation>
    </message>
    <message>
        <source>TAPPING WITH A FLOATING TAP HOLDER</source>
        <translation>ROSCAGEM COM MANDRIL COMPENSADOR</translation>
    </message>
    <message>
        <source>RIGID TAPPING</source>
        <translation>ROSCAGEM SEM MANDRIL COMPENSADOR</translation>
    </message>
    <message>
        <source>Retraction for chip breaking in pitches (0: out of the hole)</source>
        <translation>Retrocesso na rotura de apara em passos de rosca (0: fora do furo)</translation>
    </message>
    <message>
        <source>Spindle speed factor for retraction</source>
        <translation>Fator de velocidade do mandril no retrocesso</translation>
    </message>
    <message>
        <source>TAPPING WITH CHIP BREAKING</source>
        <translation>ROSCAGEM COM ROTURA DE APARA</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch {2} differs from the pitch {3} of the tool in the tool table</source>
        <translation>ciclo {1}: o passo de rosca {2} é diferente do passo {3} da ferramenta na tabela de ferramentas</translation>
    </message>
    <message>
        <source>cycle {1}: the thread pitch Q{2} is 0</source>
        <translation>ciclo {1}: o passo de rosca Q{2} é 0</translation>
    </message>
    <message>
        <source>THREAD MILLING</source>
        <translation>FRESAR ROSCA</translation>
    </message>
    <message>
        <source>THREAD MILLING/COUNTERSINKING</source>
        <translation>FRESAR ROSCA EM REBAIXAMENTO</translation>
    </message>
    <message>
        <source>THREAD DRILLING/MILLING</source>
        <translation>FRESAR ROSCA EM FURO</translation>
    </message>
    <message>
        <source>Countersink before (0) or after (1) the thread</source>
        <translation>Rebaixar antes (0) ou depois (1) da rosca</translation>
    </message>
    <message>
        <source>HELICAL THREAD DRILLING/MILLING</source>
        <translation>FRESAR ROSCA DE HÉLICE EM FURO</translation>
    </message>
    <message>
        <source>Countersinking offset at front: stud centre to tool centre</source>
        <translation>Desvio de rebaixamento frontal: centro do pino ao centro da ferramenta</translation>
    </message>
    <message>
        <source>OUTSIDE THREAD MILLING</source>
        <translation>FRESAR ROSCA EXTERIOR</translation>
    </message>
    <message>
        <source>cycle {1}: the tool diameter {2} is too large for the nominal diameter {3}</source>
        <translation>ciclo {1}: o diâmetro da ferramenta {2} é demasiado grande para o diâmetro nominal {3}</translation>
    </message>
    <message>
        <source>cycle {1}: unexpected &apos;{2}&apos;</source>
        <translation>ciclo {1}: &apos;{2}&apos; inesperado</translation>
    </message>
    <message>
        <source>cycle {1}: {2} needs a value</source>
        <translation>ciclo {1}: {2} precisa de um valor</translation>
    </message>
    <message>
        <source>cycle {1}: scaling factor {2} = {3} is outside 0.000001 to 99.999999</source>
        <translation>ciclo {1}: o fator de escala {2} = {3} está fora de 0.000001 a 99.999999</translation>
    </message>
    <message>
        <source>Datum shift per axis (IX: incremental), or #n: datum number of the datum table</source>
        <translation>Deslocação do ponto zero por eixo (IX: incremental), ou #n: número do ponto zero na tabela de pontos zero</translation>
    </message>
    <message>
        <source>Mirrored axes (none: mirroring off)</source>
        <translation>Eixos espelhados (nenhum: espelho desligado)</translation>
    </message>
    <message>
        <source>Angle of rotation (IROT: incremental)</source>
        <translation>Ângulo de rotação (IROT: incremental)</translation>
    </message>
    <message>
        <source>Scaling factor</source>
        <translation>Fator de escala</translation>
    </message>
    <message>
        <source>Scaling factor per axis</source>
        <translation>Fator de escala por eixo</translation>
    </message>
    <message>
        <source>Centre of the scaling per axis</source>
        <translation>Centro da escala por eixo</translation>
    </message>
    <message>
        <source>Number of the preset to activate</source>
        <translation>Número do ponto de referência a ativar</translation>
    </message>
    <message>
        <source>Tilt angles of the rotary axes</source>
        <translation>Ângulos de inclinação dos eixos rotativos</translation>
    </message>
    <message>
        <source>Feed rate for automatic positioning</source>
        <translation>Avanço de posicionamento automático</translation>
    </message>
    <message>
        <source>Set-up clearance for automatic positioning</source>
        <translation>Distância de segurança para o posicionamento automático</translation>
    </message>
    <message>
        <source>cycle {1}: angle of rotation ROT = {2} is outside -360 to 360</source>
        <translation>ciclo {1}: o ângulo de rotação ROT = {2} está fora de -360 a 360</translation>
    </message>
    <message>
        <source>DATUM SHIFT</source>
        <translation>DESLOCAÇÃO DO PONTO ZERO</translation>
    </message>
    <message>
        <source>MIRROR IMAGE</source>
        <translation>ESPELHO</translation>
    </message>
    <message>
        <source>ROTATION</source>
        <translation>ROTAÇÃO</translation>
    </message>
    <message>
        <source>SCALING</source>
        <translation>FATOR DE ESCALA</translation>
    </message>
    <message>
        <source>AXIS-SPECIFIC SCALING</source>
        <translation>FATOR DE ESCALA ESPECÍFICO DO EIXO</translation>
    </message>
    <message>
        <source>PRESETTING</source>
        <translation>MEMORIZAR PONTO DE REFERÊNCIA</translation>
    </message>
    <message>
        <source>WORKING PLANE</source>
        <translation>PLANO DE MAQUINAGEM</translation>
    </message>
    <message>
        <source>the block is longer than 60000 characters</source>
        <translation>o bloco tem mais de 60000 caracteres</translation>
    </message>
    <message>
        <source>empty block: a block needs at least a comment</source>
        <translation>bloco vazio: um bloco precisa pelo menos de um comentário</translation>
    </message>
    <message>
        <source>a block has at most 3 skip marks</source>
        <translation>um bloco tem no máximo 3 marcas de salto</translation>
    </message>
    <message>
        <source>a block label cannot be a parameter</source>
        <translation>um rótulo de bloco não pode ser um parâmetro</translation>
    </message>
    <message>
        <source>label number expected after N</source>
        <translation>número de rótulo esperado depois de N</translation>
    </message>
    <message>
        <source>a label has at most 8 digits (N0-N99999999)</source>
        <translation>um rótulo tem no máximo 8 algarismos (N0-N99999999)</translation>
    </message>
    <message>
        <source>missing &apos;)&apos; at the end of the high-level block</source>
        <translation>falta &apos;)&apos; no fim do bloco de alto nível</translation>
    </message>
    <message>
        <source>repetition count expected after N</source>
        <translation>número de repetições esperado depois de N</translation>
    </message>
    <message>
        <source>a repetition count has at most 4 digits (N0-N9999)</source>
        <translation>um número de repetições tem no máximo 4 algarismos (N0-N9999)</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; at the end of the block</source>
        <translation>&apos;{1}&apos; inesperado no fim do bloco</translation>
    </message>
    <message>
        <source>expressions are not allowed in ISO blocks</source>
        <translation>não são permitidas expressões em blocos ISO</translation>
    </message>
    <message>
        <source>parameter number expected after P</source>
        <translation>número de parâmetro esperado depois de P</translation>
    </message>
    <message>
        <source>number expected after the sign of {1}</source>
        <translation>número esperado depois do sinal de {1}</translation>
    </message>
    <message>
        <source>{1} cannot be negative</source>
        <translation>{1} não pode ser negativo</translation>
    </message>
    <message>
        <source>{1} value {2} is outside the format {3}.{4}</source>
        <translation>o valor {2} de {1} está fora do formato {3}.{4}</translation>
    </message>
    <message>
        <source>{1} is outside the format {2}.{3}</source>
        <translation>{1} está fora do formato {2}.{3}</translation>
    </message>
    <message>
        <source>{1} must be a whole number from {2} to {3}</source>
        <translation>{1} tem de ser um número inteiro de {2} a {3}</translation>
    </message>
    <message>
        <source>{1} is programmed twice</source>
        <translation>{1} está programado duas vezes</translation>
    </message>
    <message>
        <source>&apos;{1}&apos;: words are written in upper case</source>
        <translation>&apos;{1}&apos;: as palavras escrevem-se em maiúsculas</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos;</source>
        <translation>&apos;{1}&apos; inesperado</translation>
    </message>
    <message>
        <source>G functions are written at the start of the block</source>
        <translation>as funções G escrevem-se no início do bloco</translation>
    </message>
    <message>
        <source>too many G functions in one block</source>
        <translation>demasiadas funções G num bloco</translation>
    </message>
    <message>
        <source>axis letters after G14, G16 or G74 take no value</source>
        <translation>as letras de eixo depois de G14, G16 ou G74 não levam valor</translation>
    </message>
    <message>
        <source>I is programmed more than twice</source>
        <translation>I está programado mais de duas vezes</translation>
    </message>
    <message>
        <source>at most 7 M functions in one block</source>
        <translation>no máximo 7 funções M num bloco</translation>
    </message>
    <message>
        <source>E belongs to G51</source>
        <translation>E pertence a G51</translation>
    </message>
    <message>
        <source>unknown word &apos;{1}&apos;</source>
        <translation>palavra desconhecida &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 cannot be used in a thread</source>
        <translation>G36, G37, G38 e G39 não podem ser usadas numa rosca</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 need a move in the plane</source>
        <translation>G36, G37, G38 e G39 precisam de um movimento no plano</translation>
    </message>
    <message>
        <source>the next block must be a contour element in the plane</source>
        <translation>o bloco seguinte tem de ser um elemento de contorno no plano</translation>
    </message>
    <message>
        <source>G37 needs a straight line (G00 or G01)</source>
        <translation>G37 precisa de uma reta (G00 ou G01)</translation>
    </message>
    <message>
        <source>G37: the start point lies inside the entry circle</source>
        <translation>G37: o ponto inicial está dentro do círculo de entrada</translation>
    </message>
    <message>
        <source>G36: the rounding radius does not fit between the elements</source>
        <translation>G36: o raio de arredondamento não cabe entre os elementos</translation>
    </message>
    <message>
        <source>G39 needs straight lines on both sides</source>
        <translation>G39 precisa de retas de ambos os lados</translation>
    </message>
    <message>
        <source>G39: the chamfer is longer than an adjacent line</source>
        <translation>G39: o chanfre é mais comprido que uma reta adjacente</translation>
    </message>
    <message>
        <source>the block after G38 must be a straight line (G00 or G01)</source>
        <translation>o bloco depois de G38 tem de ser uma reta (G00 ou G01)</translation>
    </message>
    <message>
        <source>G38: the end point lies inside the exit circle</source>
        <translation>G38: o ponto final está dentro do círculo de saída</translation>
    </message>
    <message>
        <source>G36, G37, G38 and G39 need a following contour element</source>
        <translation>G36, G37, G38 e G39 precisam de um elemento de contorno seguinte</translation>
    </message>
    <message>
        <source>division by zero</source>
        <translation>divisão por zero</translation>
    </message>
    <message>
        <source>EXP: {1} to the power {2} has no value</source>
        <translation>EXP: {1} elevado a {2} não tem valor</translation>
    </message>
    <message>
        <source>MOD by zero</source>
        <translation>MOD por zero</translation>
    </message>
    <message>
        <source>&apos;)&apos; expected</source>
        <translation>&apos;)&apos; esperado</translation>
    </message>
    <message>
        <source>a function argument needs parentheses unless it is a number</source>
        <translation>o argumento de uma função precisa de parênteses, exceto se for um número</translation>
    </message>
    <message>
        <source>{1}: {2} is outside its domain</source>
        <translation>{1}: {2} está fora do seu domínio</translation>
    </message>
    <message>
        <source>a hexadecimal constant has 1 to 8 digits</source>
        <translation>uma constante hexadecimal tem 1 a 8 algarismos</translation>
    </message>
    <message>
        <source>number expected</source>
        <translation>número esperado</translation>
    </message>
    <message>
        <source>a constant has at most 6 integer and 5 decimal digits</source>
        <translation>uma constante tem no máximo 6 algarismos inteiros e 5 decimais</translation>
    </message>
    <message>
        <source>an index must be a whole number, not {1}</source>
        <translation>um índice tem de ser um número inteiro, não {1}</translation>
    </message>
    <message>
        <source>number or (expression) expected</source>
        <translation>número ou (expressão) esperado</translation>
    </message>
    <message>
        <source>GPOS needs N&lt;block&gt;</source>
        <translation>GPOS precisa de N&lt;bloco&gt;</translation>
    </message>
    <message>
        <source>GPOS needs P&lt;program&gt;</source>
        <translation>GPOS precisa de P&lt;programa&gt;</translation>
    </message>
    <message>
        <source>{1} needs a number</source>
        <translation>{1} precisa de um número</translation>
    </message>
    <message>
        <source>value expected</source>
        <translation>valor esperado</translation>
    </message>
    <message>
        <source>&apos;(&apos; expected</source>
        <translation>&apos;(&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;,&apos; expected</source>
        <translation>&apos;,&apos; esperado</translation>
    </message>
    <message>
        <source>label N{1} is not defined in this program</source>
        <translation>o rótulo N{1} não está definido neste programa</translation>
    </message>
    <message>
        <source>label N{1} is not defined in the program</source>
        <translation>o rótulo N{1} não está definido no programa</translation>
    </message>
    <message>
        <source>RPT: block N{1} comes before block N{2}</source>
        <translation>RPT: o bloco N{1} vem antes do bloco N{2}</translation>
    </message>
    <message>
        <source>more than {1} nested levels</source>
        <translation>mais de {1} níveis de imbricação</translation>
    </message>
    <message>
        <source>cannot read program {1}: {2}</source>
        <translation>não é possível ler o programa {1}: {2}</translation>
    </message>
    <message>
        <source>program {1} has errors</source>
        <translation>o programa {1} tem erros</translation>
    </message>
    <message>
        <source>program {1} is not in the NC root</source>
        <translation>o programa {1} não está na raiz NC</translation>
    </message>
    <message>
        <source>subroutine {1} is not defined</source>
        <translation>a sub-rotina {1} não está definida</translation>
    </message>
    <message>
        <source>subroutine {1} is defined in more than one program</source>
        <translation>a sub-rotina {1} está definida em mais de um programa</translation>
    </message>
    <message>
        <source>the program with subroutine {1} has errors</source>
        <translation>o programa com a sub-rotina {1} tem erros</translation>
    </message>
    <message>
        <source>error 1255: subroutine restricted to OEM programs</source>
        <translation>erro 1255: sub-rotina restrita a programas OEM</translation>
    </message>
    <message>
        <source>more than 6 nested levels of local parameters</source>
        <translation>mais de 6 níveis de imbricação de parâmetros locais</translation>
    </message>
    <message>
        <source>subroutine {1} has no RET</source>
        <translation>a sub-rotina {1} não tem RET</translation>
    </message>
    <message>
        <source>RET outside a subroutine</source>
        <translation>RET fora de uma sub-rotina</translation>
    </message>
    <message>
        <source>error 1064: program cannot be executed (MEXEC inside the modal program)</source>
        <translation>erro 1064: o programa não pode ser executado (MEXEC dentro do programa modal)</translation>
    </message>
    <message>
        <source>REPOS is only allowed in an interrupt subroutine</source>
        <translation>REPOS só é permitido numa sub-rotina de interrupção</translation>
    </message>
    <message>
        <source>REPOS failed</source>
        <translation>REPOS falhou</translation>
    </message>
    <message>
        <source>collision detection removed a loop of the compensated path</source>
        <translation>a deteção de colisões removeu um laço da trajetória compensada</translation>
    </message>
    <message>
        <source>the program ends before the last block of the RPT</source>
        <translation>o programa termina antes do último bloco do RPT</translation>
    </message>
    <message>
        <source>the program ends inside a subroutine (RET missing)</source>
        <translation>o programa termina dentro de uma sub-rotina (falta RET)</translation>
    </message>
    <message>
        <source>axis {1} is not available on this machine</source>
        <translation>o eixo {1} não existe nesta máquina</translation>
    </message>
    <message>
        <source>N{1}: only a motion block under a modal subroutine (MCALL, MEXEC) or a canned cycle can be repeated</source>
        <translation>N{1}: só se pode repetir um bloco de movimento sob uma sub-rotina modal (MCALL, MEXEC) ou um ciclo fixo</translation>
    </message>
    <message>
        <source>incompatible G functions G51 and {1} (error 7)</source>
        <translation>funções G incompatíveis G51 e {1} (erro 7)</translation>
    </message>
    <message>
        <source>G40, G41 and G42 need G00 or G01 active, not G02/G03</source>
        <translation>G40, G41 e G42 precisam de G00 ou G01 ativa, não G02/G03</translation>
    </message>
    <message>
        <source>radius compensation works in the ZX plane only (PLACOMP 0)</source>
        <translation>a compensação de raio só funciona no plano ZX (PLACOMP 0)</translation>
    </message>
    <message>
        <source>{1} needs R greater than 0 right after it</source>
        <translation>{1} precisa de R maior que 0 logo a seguir</translation>
    </message>
    <message>
        <source>G37 needs R greater than 0 right after it</source>
        <translation>G37 precisa de R maior que 0 logo a seguir</translation>
    </message>
    <message>
        <source>G37 needs a straight line (G00 or G01), not G02/G03</source>
        <translation>G37 precisa de uma reta (G00 ou G01), não G02/G03</translation>
    </message>
    <message>
        <source>G06 belongs in a circular interpolation block</source>
        <translation>G06 pertence a um bloco de interpolação circular</translation>
    </message>
    <message>
        <source>G16 needs two axis letters: abscissa and ordinate</source>
        <translation>G16 precisa de duas letras de eixo: abcissa e ordenada</translation>
    </message>
    <message>
        <source>G16 {1}{2}: only planes of two of the axes X, Y and Z are supported</source>
        <translation>G16 {1}{2}: só são suportados planos formados por dois dos eixos X, Y e Z</translation>
    </message>
    <message>
        <source>the plane cannot change under radius compensation</source>
        <translation>o plano não pode mudar com a compensação de raio ativa</translation>
    </message>
    <message>
        <source>G51 needs E, the permitted contour error</source>
        <translation>G51 precisa de E, o erro de contorno admissível</translation>
    </message>
    <message>
        <source>G72 S: the scale factor must be greater than 0</source>
        <translation>G72 S: o fator de escala tem de ser maior que 0</translation>
    </message>
    <message>
        <source>G72 needs S or axis factors</source>
        <translation>G72 precisa de S ou de fatores por eixo</translation>
    </message>
    <message>
        <source>G72: the scale factor of {1} must be greater than 0</source>
        <translation>G72: o fator de escala de {1} tem de ser maior que 0</translation>
    </message>
    <message>
        <source>{1} needs K, the zone number 1-4</source>
        <translation>{1} precisa de K, o número da zona 1-4</translation>
    </message>
    <message>
        <source>G22 needs S0 (off), S1 (no entry) or S2 (no exit)</source>
        <translation>G22 precisa de S0 (desligada), S1 (sem entrada) ou S2 (sem saída)</translation>
    </message>
    <message>
        <source>G74 alone runs the subroutine of REFPSUB, which is not set</source>
        <translation>G74 sozinha executa a sub-rotina de REFPSUB, que não está definida</translation>
    </message>
    <message>
        <source>G159 needs N1-N20</source>
        <translation>G159 precisa de N1-N20</translation>
    </message>
    <message>
        <source>G96 needs S: no cutting speed was programmed before</source>
        <translation>G96 precisa de S: não foi programada velocidade de corte antes</translation>
    </message>
    <message>
        <source>G96 needs a spindle gear range (M41-M44) first</source>
        <translation>G96 precisa primeiro de uma gama de velocidades do mandril (M41-M44)</translation>
    </message>
    <message>
        <source>S{1} is above the spindle limit of {2} rpm</source>
        <translation>S{1} está acima do limite do mandril de {2} rpm</translation>
    </message>
    <message>
        <source>M{1} has a subroutine: it must be alone in its block</source>
        <translation>M{1} tem uma sub-rotina: tem de estar sozinha no seu bloco</translation>
    </message>
    <message>
        <source>polar coordinates (R, Q) and Cartesian coordinates of the plane in one block</source>
        <translation>coordenadas polares (R, Q) e coordenadas cartesianas do plano no mesmo bloco</translation>
    </message>
    <message>
        <source>the polar radius becomes negative</source>
        <translation>o raio polar torna-se negativo</translation>
    </message>
    <message>
        <source>an angle Q with both coordinates of the plane</source>
        <translation>um ângulo Q com ambas as coordenadas do plano</translation>
    </message>
    <message>
        <source>angle Q {1}: the path cannot reach that abscissa</source>
        <translation>ângulo Q {1}: a trajetória não consegue atingir essa abcissa</translation>
    </message>
    <message>
        <source>angle Q {1}: the path cannot reach that ordinate</source>
        <translation>ângulo Q {1}: a trajetória não consegue atingir essa ordenada</translation>
    </message>
    <message>
        <source>J is the centre of the Y axis: the ZX plane uses I and K</source>
        <translation>J é o centro do eixo Y: o plano ZX usa I e K</translation>
    </message>
    <message>
        <source>G08 needs a previous path in the plane to be tangent to</source>
        <translation>G08 precisa de uma trajetória anterior no plano à qual ser tangente</translation>
    </message>
    <message>
        <source>G08 cannot program a full circle</source>
        <translation>G08 não pode programar um círculo completo</translation>
    </message>
    <message>
        <source>G08: the end point lies on the tangent of the previous path</source>
        <translation>G08: o ponto final está na tangente da trajetória anterior</translation>
    </message>
    <message>
        <source>G09 cannot program a full circle</source>
        <translation>G09 não pode programar um círculo completo</translation>
    </message>
    <message>
        <source>G09: the three points lie on a line</source>
        <translation>G09: os três pontos estão numa reta</translation>
    </message>
    <message>
        <source>a full circle cannot be programmed with R</source>
        <translation>um círculo completo não pode ser programado com R</translation>
    </message>
    <message>
        <source>the arc radius R is too small for the end point</source>
        <translation>o raio R do arco é demasiado pequeno para o ponto final</translation>
    </message>
    <message>
        <source>the start and end radii differ by {1} mm (more than CIRINERR)</source>
        <translation>os raios inicial e final diferem em {1} mm (mais do que CIRINERR)</translation>
    </message>
    <message>
        <source>the arc has no radius</source>
        <translation>o arco não tem raio</translation>
    </message>
    <message>
        <source>arc centre or radius beyond 214748.3647 mm</source>
        <translation>centro ou raio do arco além de 214748.3647 mm</translation>
    </message>
    <message>
        <source>Q (spindle angle) needs M19TYPE = 1</source>
        <translation>Q (ângulo do mandril) precisa de M19TYPE = 1</translation>
    </message>
    <message>
        <source>only the first thread of a joined chain may have Q</source>
        <translation>só a primeira rosca de uma cadeia encadeada pode ter Q</translation>
    </message>
    <message>
        <source>Q must be within +-359.9999 degrees</source>
        <translation>Q tem de estar dentro de +-359.9999 graus</translation>
    </message>
    <message>
        <source>a thread needs its pitch L</source>
        <translation>uma rosca precisa do seu passo L</translation>
    </message>
    <message>
        <source>two variable-pitch threads cannot be joined; end one with G34 L0 K0</source>
        <translation>duas roscas de passo variável não podem ser encadeadas; termine uma com G34 L0 K0</translation>
    </message>
    <message>
        <source>G34 joined to G33 must start with the pitch of the G33</source>
        <translation>G34 encadeada com G33 tem de começar com o passo da G33</translation>
    </message>
    <message>
        <source>after G34 a constant pitch is programmed with G34 L0 K0</source>
        <translation>depois de G34 programa-se um passo constante com G34 L0 K0</translation>
    </message>
    <message>
        <source>the thread pitch must be greater than 0</source>
        <translation>o passo de rosca tem de ser maior que 0</translation>
    </message>
    <message>
        <source>the variable pitch reaches zero before the end point</source>
        <translation>o passo variável chega a zero antes do ponto final</translation>
    </message>
    <message>
        <source>G53 works with G00 and G01 moves only</source>
        <translation>G53 só funciona com movimentos G00 e G01</translation>
    </message>
    <message>
        <source>G52 moves one axis</source>
        <translation>G52 move um eixo</translation>
    </message>
    <message>
        <source>no tool offset table: offset D{1} and the following ones are all zero</source>
        <translation>sem tabela de corretores de ferramenta: o corretor D{1} e os seguintes são todos zero</translation>
    </message>
    <message>
        <source>the header should be %comment,attributes, (two commas)</source>
        <translation>o cabeçalho deve ser %comentário,atributos, (duas vírgulas)</translation>
    </message>
    <message>
        <source>the program comment has more than 20 characters</source>
        <translation>o comentário do programa tem mais de 20 caracteres</translation>
    </message>
    <message>
        <source>words out of the order G, coordinates, F, S, T, D, M</source>
        <translation>palavras fora da ordem G, coordenadas, F, S, T, D, M</translation>
    </message>
    <message>
        <source>subroutine {1} starts before subroutine {2} has its RET</source>
        <translation>a sub-rotina {1} começa antes de a sub-rotina {2} ter o seu RET</translation>
    </message>
    <message>
        <source>error 63: program subroutine numbers from 1 to 9999 (10000-20000 only in OEM programs)</source>
        <translation>erro 63: programe números de sub-rotina de 1 a 9999 (10000-20000 só em programas OEM)</translation>
    </message>
    <message>
        <source>subroutine {1} is defined twice</source>
        <translation>a sub-rotina {1} está definida duas vezes</translation>
    </message>
    <message>
        <source>programs on a PC over DNC are not available; the program cannot run past this block</source>
        <translation>não há programas num PC por DNC; o programa não pode continuar para além deste bloco</translation>
    </message>
    <message>
        <source>label N{1} is used more than once; jumps go to the first one</source>
        <translation>o rótulo N{1} é usado mais de uma vez; os saltos vão para o primeiro</translation>
    </message>
    <message>
        <source>incompatible G functions</source>
        <translation>funções G incompatíveis</translation>
    </message>
    <message>
        <source>program subroutine number from 1 to 9999</source>
        <translation>programe o número de sub-rotina de 1 a 9999</translation>
    </message>
    <message>
        <source>the S that changes the gear range must be alone in its block</source>
        <translation>o S que muda a gama de velocidades tem de estar sozinho no seu bloco</translation>
    </message>
    <message>
        <source>program cannot be executed</source>
        <translation>o programa não pode ser executado</translation>
    </message>
    <message>
        <source>subroutine restricted to OEM program</source>
        <translation>sub-rotina restrita a programas OEM</translation>
    </message>
    <message>
        <source>{1}</source>
        <translation>{1}</translation>
    </message>
    <message>
        <source>error {1}</source>
        <translation>erro {1}</translation>
    </message>
    <message>
        <source>error {1}: {2}</source>
        <translation>erro {1}: {2}</translation>
    </message>
    <message>
        <source>DGWZ: Z minimum &lt; Z maximum and 0 &lt;= inner &lt; outer</source>
        <translation>DGWZ: Z mínimo &lt; Z máximo e 0 &lt;= interior &lt; exterior</translation>
    </message>
    <message>
        <source>program {1} exists: OPEN needs A (append) or D (delete)</source>
        <translation>o programa {1} existe: OPEN precisa de A (acrescentar) ou D (apagar)</translation>
    </message>
    <message>
        <source>program {1} is running: it cannot be opened</source>
        <translation>o programa {1} está em execução: não pode ser aberto</translation>
    </message>
    <message>
        <source>WRITE needs a program opened with OPEN</source>
        <translation>WRITE precisa de um programa aberto com OPEN</translation>
    </message>
    <message>
        <source>GPOS: program {1} has no block N{2}</source>
        <translation>GPOS: o programa {1} não tem o bloco N{2}</translation>
    </message>
    <message>
        <source>GPOS: block not found</source>
        <translation>GPOS: bloco não encontrado</translation>
    </message>
    <message>
        <source>{1} is not available on the simulated machine</source>
        <translation>{1} não está disponível na máquina simulada</translation>
    </message>
    <message>
        <source>{1} cannot be read from a part program (PLC or DNC only)</source>
        <translation>{1} não pode ser lida num programa de peça (só PLC ou DNC)</translation>
    </message>
    <message>
        <source>{1}: the simulated machine has no tool magazine</source>
        <translation>{1}: a máquina simulada não tem armazém de ferramentas</translation>
    </message>
    <message>
        <source>{1}: offsets are numbered 0-255</source>
        <translation>{1}: os corretores são numerados 0-255</translation>
    </message>
    <message>
        <source>{1}: zero offsets are 54-59 and 1-20</source>
        <translation>{1}: as origens são 54-59 e 1-20</translation>
    </message>
    <message>
        <source>NBTOOL can only be read in the tool change subroutine</source>
        <translation>NBTOOL só pode ser lida na sub-rotina de troca de ferramenta</translation>
    </message>
    <message>
        <source>MS{1}: the state is kept for M00-M06, M08, M09, M19, M30 and M41-M44</source>
        <translation>MS{1}: o estado é mantido para M00-M06, M08, M09, M19, M30 e M41-M44</translation>
    </message>
    <message>
        <source>{1}: outputs 1-8</source>
        <translation>{1}: saídas 1-8</translation>
    </message>
    <message>
        <source>{1} is read-only in a part program</source>
        <translation>{1} é só de leitura num programa de peça</translation>
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
        <translation>{1}: os corretores são D1-D255 e F é 0-9</translation>
    </message>
    <message>
        <source>{1}: value out of range</source>
        <translation>{1}: valor fora dos limites</translation>
    </message>
    <message>
        <source>KEY can only be written in a customisation program</source>
        <translation>KEY só pode ser escrita num programa de personalização</translation>
    </message>
    <message>
        <source>KEYSRC can only be changed while it is 0</source>
        <translation>KEYSRC só pode ser alterada enquanto vale 0</translation>
    </message>
    <message>
        <source>{1}: free outputs 1-4, -10 to 10 V</source>
        <translation>{1}: saídas livres 1-4, -10 a 10 V</translation>
    </message>
    <message>
        <source>rapid positioning</source>
        <translation>posicionamento rápido</translation>
    </message>
    <message>
        <source>linear interpolation</source>
        <translation>interpolação linear</translation>
    </message>
    <message>
        <source>circular interpolation clockwise</source>
        <translation>interpolação circular no sentido horário</translation>
    </message>
    <message>
        <source>circular interpolation counter-clockwise</source>
        <translation>interpolação circular no sentido anti-horário</translation>
    </message>
    <message>
        <source>dwell / stop block preparation</source>
        <translation>temporização / paragem da preparação de blocos</translation>
    </message>
    <message>
        <source>round corner</source>
        <translation>aresta arredondada</translation>
    </message>
    <message>
        <source>arc centre in absolute coordinates</source>
        <translation>centro do arco em coordenadas absolutas</translation>
    </message>
    <message>
        <source>sharp corner</source>
        <translation>aresta viva</translation>
    </message>
    <message>
        <source>arc tangent to the previous path</source>
        <translation>arco tangente à trajetória anterior</translation>
    </message>
    <message>
        <source>arc through three points</source>
        <translation>arco por três pontos</translation>
    </message>
    <message>
        <source>mirror image off</source>
        <translation>imagem espelho desligada</translation>
    </message>
    <message>
        <source>mirror image in X</source>
        <translation>imagem espelho em X</translation>
    </message>
    <message>
        <source>mirror image in Y</source>
        <translation>imagem espelho em Y</translation>
    </message>
    <message>
        <source>mirror image in Z</source>
        <translation>imagem espelho em Z</translation>
    </message>
    <message>
        <source>mirror image in the programmed axes</source>
        <translation>imagem espelho nos eixos programados</translation>
    </message>
    <message>
        <source>main plane by two axes</source>
        <translation>plano principal por dois eixos</translation>
    </message>
    <message>
        <source>main plane XY</source>
        <translation>plano principal XY</translation>
    </message>
    <message>
        <source>main plane ZX</source>
        <translation>plano principal ZX</translation>
    </message>
    <message>
        <source>main plane YZ</source>
        <translation>plano principal YZ</translation>
    </message>
    <message>
        <source>work zone lower limits</source>
        <translation>limites inferiores da zona de trabalho</translation>
    </message>
    <message>
        <source>work zone upper limits</source>
        <translation>limites superiores da zona de trabalho</translation>
    </message>
    <message>
        <source>work zone enable/disable</source>
        <translation>ativar/desativar zona de trabalho</translation>
    </message>
    <message>
        <source>feed as inverse of time</source>
        <translation>avanço como inverso do tempo</translation>
    </message>
    <message>
        <source>electronic threading</source>
        <translation>roscagem eletrónica</translation>
    </message>
    <message>
        <source>variable-pitch threading</source>
        <translation>roscagem de passo variável</translation>
    </message>
    <message>
        <source>corner rounding</source>
        <translation>arredondamento de arestas</translation>
    </message>
    <message>
        <source>tangential entry</source>
        <translation>entrada tangencial</translation>
    </message>
    <message>
        <source>tangential exit</source>
        <translation>saída tangencial</translation>
    </message>
    <message>
        <source>chamfer</source>
        <translation>chanfre</translation>
    </message>
    <message>
        <source>radius compensation off</source>
        <translation>compensação de raio desligada</translation>
    </message>
    <message>
        <source>radius compensation left</source>
        <translation>compensação de raio à esquerda</translation>
    </message>
    <message>
        <source>radius compensation right</source>
        <translation>compensação de raio à direita</translation>
    </message>
    <message>
        <source>inclined-axis transformation</source>
        <translation>transformação de eixo inclinado</translation>
    </message>
    <message>
        <source>controlled round corner</source>
        <translation>aresta arredondada controlada</translation>
    </message>
    <message>
        <source>look-ahead</source>
        <translation>antecipação (look-ahead)</translation>
    </message>
    <message>
        <source>move to hard stop</source>
        <translation>deslocação até batente</translation>
    </message>
    <message>
        <source>coordinates from machine zero</source>
        <translation>coordenadas a partir do zero máquina</translation>
    </message>
    <message>
        <source>absolute zero offset 1</source>
        <translation>origem absoluta 1</translation>
    </message>
    <message>
        <source>absolute zero offset 2</source>
        <translation>origem absoluta 2</translation>
    </message>
    <message>
        <source>absolute zero offset 3</source>
        <translation>origem absoluta 3</translation>
    </message>
    <message>
        <source>absolute zero offset 4</source>
        <translation>origem absoluta 4</translation>
    </message>
    <message>
        <source>additive zero offset 1</source>
        <translation>origem aditiva 1</translation>
    </message>
    <message>
        <source>additive zero offset 2</source>
        <translation>origem aditiva 2</translation>
    </message>
    <message>
        <source>pattern repeat cycle</source>
        <translation>ciclo de seguimento de perfil</translation>
    </message>
    <message>
        <source>stock removal cycle along X</source>
        <translation>ciclo de desbaste ao longo de X</translation>
    </message>
    <message>
        <source>stock removal cycle along Z</source>
        <translation>ciclo de desbaste ao longo de Z</translation>
    </message>
    <message>
        <source>programming in inches</source>
        <translation>programação em polegadas</translation>
    </message>
    <message>
        <source>programming in millimetres</source>
        <translation>programação em milímetros</translation>
    </message>
    <message>
        <source>scaling factor</source>
        <translation>fator de escala</translation>
    </message>
    <message>
        <source>machine reference search</source>
        <translation>procura de referência máquina</translation>
    </message>
    <message>
        <source>probing move until touching</source>
        <translation>movimento de apalpação até tocar</translation>
    </message>
    <message>
        <source>probing move until no longer touching</source>
        <translation>movimento de apalpação até deixar de tocar</translation>
    </message>
    <message>
        <source>turning cycle, straight sections</source>
        <translation>ciclo de torneamento, troços retos</translation>
    </message>
    <message>
        <source>facing cycle, straight sections</source>
        <translation>ciclo de facejamento, troços retos</translation>
    </message>
    <message>
        <source>drilling cycle</source>
        <translation>ciclo de furação</translation>
    </message>
    <message>
        <source>turning cycle, curved sections</source>
        <translation>ciclo de torneamento, troços curvos</translation>
    </message>
    <message>
        <source>facing cycle, curved sections</source>
        <translation>ciclo de facejamento, troços curvos</translation>
    </message>
    <message>
        <source>longitudinal threading cycle</source>
        <translation>ciclo de roscagem longitudinal</translation>
    </message>
    <message>
        <source>face threading cycle</source>
        <translation>ciclo de roscagem frontal</translation>
    </message>
    <message>
        <source>grooving cycle along X</source>
        <translation>ciclo de ranhuragem ao longo de X</translation>
    </message>
    <message>
        <source>grooving cycle along Z</source>
        <translation>ciclo de ranhuragem ao longo de Z</translation>
    </message>
    <message>
        <source>absolute programming</source>
        <translation>programação absoluta</translation>
    </message>
    <message>
        <source>incremental programming</source>
        <translation>programação incremental</translation>
    </message>
    <message>
        <source>coordinate preset / spindle speed limit</source>
        <translation>pré-seleção de coordenadas / limite de velocidade do mandril</translation>
    </message>
    <message>
        <source>polar origin preset</source>
        <translation>pré-seleção da origem polar</translation>
    </message>
    <message>
        <source>feed per minute</source>
        <translation>avanço por minuto</translation>
    </message>
    <message>
        <source>feed per revolution</source>
        <translation>avanço por rotação</translation>
    </message>
    <message>
        <source>constant surface speed</source>
        <translation>velocidade de corte constante</translation>
    </message>
    <message>
        <source>spindle speed in rpm</source>
        <translation>velocidade do mandril em rpm</translation>
    </message>
    <message>
        <source>X in diameter</source>
        <translation>X em diâmetro</translation>
    </message>
    <message>
        <source>X in radius</source>
        <translation>X em raio</translation>
    </message>
    <message>
        <source>absolute zero offset N1-N20</source>
        <translation>origem absoluta N1-N20</translation>
    </message>
    <message>
        <source>axis retraction when threading stops</source>
        <translation>retrocesso do eixo quando a roscagem para</translation>
    </message>
    <message>
        <source>{1} does not exist on the 8035 T</source>
        <translation>{1} não existe no 8035 T</translation>
    </message>
    <message>
        <source>{1} ({2}) is not supported</source>
        <translation>{1} ({2}) não é suportado</translation>
    </message>
    <message>
        <source>incompatible G functions {1} and {2} (error 7)</source>
        <translation>funções G incompatíveis {1} e {2} (erro 7)</translation>
    </message>
    <message>
        <source>{1} must be alone in its block</source>
        <translation>{1} tem de estar sozinho no seu bloco</translation>
    </message>
    <message>
        <source>tool radius too large</source>
        <translation>raio da ferramenta demasiado grande</translation>
    </message>
    <message>
        <source>tool radius too large: the offset swallows this element</source>
        <translation>raio da ferramenta demasiado grande: a compensação engole este elemento</translation>
    </message>
    <message>
        <source>tool radius too large for this arc</source>
        <translation>raio da ferramenta demasiado grande para este arco</translation>
    </message>
    <message>
        <source>G40 needs a straight line (G00 or G01)</source>
        <translation>G40 precisa de uma reta (G00 ou G01)</translation>
    </message>
    <message>
        <source>48 blocks without motion in the plane under radius compensation</source>
        <translation>48 blocos sem movimento no plano com compensação de raio</translation>
    </message>
    <message>
        <source>the move violates work zone 1</source>
        <translation>o movimento viola a zona de trabalho 1</translation>
    </message>
    <message>
        <source>the move violates work zone 2</source>
        <translation>o movimento viola a zona de trabalho 2</translation>
    </message>
    <message>
        <source>the move violates work zone 3</source>
        <translation>o movimento viola a zona de trabalho 3</translation>
    </message>
    <message>
        <source>the move violates work zone 4</source>
        <translation>o movimento viola a zona de trabalho 4</translation>
    </message>
    <message>
        <source>the move violates work zone 5</source>
        <translation>o movimento viola a zona de trabalho 5</translation>
    </message>
    <message>
        <source>an arc cannot be scaled differently along the two axes of its plane (G72)</source>
        <translation>um arco não pode ter escalas diferentes nos dois eixos do seu plano (G72)</translation>
    </message>
    <message>
        <source>P{1}: an interrupt subroutine may only use global parameters</source>
        <translation>P{1}: uma sub-rotina de interrupção só pode usar parâmetros globais</translation>
    </message>
    <message>
        <source>P{1}: OEM parameters are only for programs with the O attribute</source>
        <translation>P{1}: os parâmetros OEM são só para programas com o atributo O</translation>
    </message>
    <message>
        <source>P{1} does not exist (P0-P25, P100-P299, P1000-P1255, P2000-P2255)</source>
        <translation>P{1} não existe (P0-P25, P100-P299, P1000-P1255, P2000-P2255)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; expected</source>
        <translation>&apos;{1}&apos; esperado</translation>
    </message>
    <message>
        <source>{1} must be a whole number from {2} to {3}, not {4}</source>
        <translation>{1} tem de ser um número inteiro de {2} a {3}, não {4}</translation>
    </message>
    <message>
        <source>a label has at most 8 digits</source>
        <translation>um rótulo tem no máximo 8 algarismos</translation>
    </message>
    <message>
        <source>text in quotes expected</source>
        <translation>texto entre aspas esperado</translation>
    </message>
    <message>
        <source>missing closing quote</source>
        <translation>falta a aspa de fecho</translation>
    </message>
    <message>
        <source>empty high-level block</source>
        <translation>bloco de alto nível vazio</translation>
    </message>
    <message>
        <source>IF cannot be nested</source>
        <translation>IF não pode ser imbricado</translation>
    </message>
    <message>
        <source>SUB cannot be the action of an IF</source>
        <translation>SUB não pode ser a ação de um IF</translation>
    </message>
    <message>
        <source>subroutine number 0-20000 expected after SUB</source>
        <translation>número de sub-rotina 0-20000 esperado depois de SUB</translation>
    </message>
    <message>
        <source>at most 26 assignments to different targets</source>
        <translation>no máximo 26 atribuições a destinos diferentes</translation>
    </message>
    <message>
        <source>parameter or variable expected</source>
        <translation>parâmetro ou variável esperado</translation>
    </message>
    <message>
        <source>a subroutine call passes local parameters (P0-P25, A-Z)</source>
        <translation>uma chamada de sub-rotina passa parâmetros locais (P0-P25, A-Z)</translation>
    </message>
    <message>
        <source>&apos;=&apos; expected</source>
        <translation>&apos;=&apos; esperado</translation>
    </message>
    <message>
        <source>a subroutine call passes local parameters P0-P25, not P{1}</source>
        <translation>uma chamada de sub-rotina passa parâmetros locais P0-P25, não P{1}</translation>
    </message>
    <message>
        <source>error number expected</source>
        <translation>número de erro esperado</translation>
    </message>
    <message>
        <source>ERROR takes a number, a parameter P0-P299 or a text</source>
        <translation>ERROR aceita um número, um parâmetro P0-P299 ou um texto</translation>
    </message>
    <message>
        <source>CALL passes no parameters: use PCALL or MCALL</source>
        <translation>CALL não passa parâmetros: use PCALL ou MCALL</translation>
    </message>
    <message>
        <source>at most 26 parameters</source>
        <translation>no máximo 26 parâmetros</translation>
    </message>
    <message>
        <source>programs on a PC over DNC are not available: only programs in the NC root</source>
        <translation>não há programas num PC por DNC: só programas na raiz NC</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in {2}</source>
        <translation>&apos;{1}&apos; inesperado em {2}</translation>
    </message>
    <message>
        <source>axis letter expected in REPOS</source>
        <translation>letra de eixo esperada em REPOS</translation>
    </message>
    <message>
        <source>too many axes in REPOS</source>
        <translation>demasiados eixos em REPOS</translation>
    </message>
    <message>
        <source>INPUT expected</source>
        <translation>INPUT esperado</translation>
    </message>
    <message>
        <source>DW expected</source>
        <translation>DW esperado</translation>
    </message>
    <message>
        <source>SK expected</source>
        <translation>SK esperado</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a row key</source>
        <translation>&apos;{1}&apos; não é uma chave de linha</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a field (letters and a number)</source>
        <translation>&apos;{1}&apos; não é um campo (letras e um número)</translation>
    </message>
    <message>
        <source>row {1} appears twice</source>
        <translation>a linha {1} aparece duas vezes</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a tool offset (D0-D255)</source>
        <translation>&apos;{1}&apos; não é um corretor de ferramenta (D0-D255)</translation>
    </message>
    <message>
        <source>unknown field &apos;{1}&apos; (X Z F R I K)</source>
        <translation>campo desconhecido &apos;{1}&apos; (X Z F R I K)</translation>
    </message>
    <message>
        <source>the location code F must be a whole number 0-9</source>
        <translation>o código de localização F tem de ser um número inteiro 0-9</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a tool (T&lt;number&gt;)</source>
        <translation>&apos;{1}&apos; não é uma ferramenta (T&lt;número&gt;)</translation>
    </message>
    <message>
        <source>unknown field &apos;{1}&apos; (D FAM NLIFE RLIFE NOSEA NOSEW CUTA)</source>
        <translation>campo desconhecido &apos;{1}&apos; (D FAM NLIFE RLIFE NOSEA NOSEW CUTA)</translation>
    </message>
    <message>
        <source>{1} must be a whole number 0-255</source>
        <translation>{1} tem de ser um número inteiro 0-255</translation>
    </message>
    <message>
        <source>G159 selects offsets N1-N20</source>
        <translation>G159 seleciona as origens N1-N20</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; cannot be part of the ACTIVE selection</source>
        <translation>&apos;{1}&apos; não pode fazer parte da seleção ACTIVE</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a zero offset (G54-G59, G159N7-G159N20, PLC, ACTIVE)</source>
        <translation>&apos;{1}&apos; não é uma origem (G54-G59, G159N7-G159N20, PLC, ACTIVE)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not an axis</source>
        <translation>&apos;{1}&apos; não é um eixo</translation>
    </message>
    <message>
        <source>the feed rate must not be negative</source>
        <translation>o avanço não pode ser negativo</translation>
    </message>
    <message>
        <source>M function number expected</source>
        <translation>número de função M esperado</translation>
    </message>
    <message>
        <source>too many M functions in one block</source>
        <translation>demasiadas funções M num bloco</translation>
    </message>
    <message>
        <source>axis {1} is programmed twice</source>
        <translation>o eixo {1} está programado duas vezes</translation>
    </message>
    <message>
        <source>DR+ or DR- expected</source>
        <translation>DR+ ou DR- esperado</translation>
    </message>
    <message>
        <source>CR needs a radius R</source>
        <translation>CR precisa de um raio R</translation>
    </message>
    <message>
        <source>the rounding radius must be positive</source>
        <translation>o raio de arredondamento tem de ser positivo</translation>
    </message>
    <message>
        <source>the chamfer length must be positive</source>
        <translation>o comprimento do chanfre tem de ser positivo</translation>
    </message>
    <message>
        <source>FMAX is not allowed here</source>
        <translation>FMAX não é permitido aqui</translation>
    </message>
    <message>
        <source>LT, LN, CT or LCT expected after {1}</source>
        <translation>LT, LN, CT ou LCT esperado depois de {1}</translation>
    </message>
    <message>
        <source>REP must be between 0 and 65534</source>
        <translation>REP tem de estar entre 0 e 65534</translation>
    </message>
    <message>
        <source>program name expected</source>
        <translation>nome de programa esperado</translation>
    </message>
    <message>
        <source>LBL or PGM expected after CALL</source>
        <translation>LBL ou PGM esperado depois de CALL</translation>
    </message>
    <message>
        <source>tool number out of range</source>
        <translation>número de ferramenta fora dos limites</translation>
    </message>
    <message>
        <source>the spindle speed must not be negative</source>
        <translation>a velocidade do mandril não pode ser negativa</translation>
    </message>
    <message>
        <source>CALL or DEF expected after TOOL</source>
        <translation>CALL ou DEF esperado depois de TOOL</translation>
    </message>
    <message>
        <source>PGM expected</source>
        <translation>PGM esperado</translation>
    </message>
    <message>
        <source>MM or INCH expected</source>
        <translation>MM ou INCH esperado</translation>
    </message>
    <message>
        <source>FORM expected</source>
        <translation>FORM esperado</translation>
    </message>
    <message>
        <source>axis expected</source>
        <translation>eixo esperado</translation>
    </message>
    <message>
        <source>0.1, 0.2 or CYLINDER expected</source>
        <translation>0.1, 0.2 ou CYLINDER esperado</translation>
    </message>
    <message>
        <source>tool axis expected</source>
        <translation>eixo da ferramenta esperado</translation>
    </message>
    <message>
        <source>Q parameter expected</source>
        <translation>parâmetro Q esperado</translation>
    </message>
    <message>
        <source>DECLARE STRING needs a QS parameter</source>
        <translation>DECLARE STRING precisa de um parâmetro QS</translation>
    </message>
    <message>
        <source>FN number expected</source>
        <translation>número de FN esperado</translation>
    </message>
    <message>
        <source>&apos;:&apos; expected after FN {1}</source>
        <translation>&apos;:&apos; esperado depois de FN {1}</translation>
    </message>
    <message>
        <source>square root of a negative number</source>
        <translation>raiz quadrada de um número negativo</translation>
    </message>
    <message>
        <source>&apos;IF&apos; expected</source>
        <translation>&apos;IF&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;GOTO&apos; expected</source>
        <translation>&apos;GOTO&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;LBL&apos; expected</source>
        <translation>&apos;LBL&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;ERROR&apos; expected</source>
        <translation>&apos;ERROR&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;PRINT&apos; expected</source>
        <translation>&apos;PRINT&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;F-PRINT&apos; expected</source>
        <translation>&apos;F-PRINT&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;mask file / output file&apos; expected</source>
        <translation>&apos;ficheiro de máscara / ficheiro de saída&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;SYSREAD&apos; expected</source>
        <translation>&apos;SYSREAD&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;ID&apos; expected</source>
        <translation>&apos;ID&apos; esperado</translation>
    </message>
    <message>
        <source>&apos;CDATA&apos; expected</source>
        <translation>&apos;CDATA&apos; esperado</translation>
    </message>
    <message>
        <source>the parameter range runs past the last Q parameter</source>
        <translation>a gama de parâmetros ultrapassa o último parâmetro Q</translation>
    </message>
    <message>
        <source>&apos;TABOPEN&apos; expected</source>
        <translation>&apos;TABOPEN&apos; esperado</translation>
    </message>
    <message>
        <source>table name expected</source>
        <translation>nome de tabela esperado</translation>
    </message>
    <message>
        <source>&apos;/&apos; expected</source>
        <translation>&apos;/&apos; esperado</translation>
    </message>
    <message>
        <source>column names in quotes expected</source>
        <translation>nomes de colunas entre aspas esperados</translation>
    </message>
    <message>
        <source>FN {1} does not exist</source>
        <translation>FN {1} não existe</translation>
    </message>
    <message>
        <source>DEF or CALL expected after CYCL</source>
        <translation>DEF ou CALL esperado depois de CYCL</translation>
    </message>
    <message>
        <source>file name expected</source>
        <translation>nome de ficheiro esperado</translation>
    </message>
    <message>
        <source>unknown block &apos;CYCLE&apos; (the keyword is CYCL)</source>
        <translation>bloco desconhecido &apos;CYCLE&apos; (a palavra-chave é CYCL)</translation>
    </message>
    <message>
        <source>unknown block &apos;{1}&apos;</source>
        <translation>bloco desconhecido &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>label name must not be empty</source>
        <translation>o nome do label não pode estar vazio</translation>
    </message>
    <message>
        <source>label expected</source>
        <translation>label esperado</translation>
    </message>
    <message>
        <source>label number or name expected</source>
        <translation>número ou nome de label esperado</translation>
    </message>
    <message>
        <source>label number must be between {1} and 65535</source>
        <translation>o número de label tem de estar entre {1} e 65535</translation>
    </message>
    <message>
        <source>cycle number expected</source>
        <translation>número de ciclo esperado</translation>
    </message>
    <message>
        <source>cycle parameter Qnnn= expected</source>
        <translation>parâmetro de ciclo Qnnn= esperado</translation>
    </message>
    <message>
        <source>cycle parameter number expected</source>
        <translation>número de parâmetro de ciclo esperado</translation>
    </message>
    <message>
        <source>GLOBAL DEF group number expected</source>
        <translation>número de grupo GLOBAL DEF esperado</translation>
    </message>
    <message>
        <source>pattern element POS, ROW, PAT, FRAME, CIRC or PITCHCIRC expected</source>
        <translation>elemento de padrão POS, ROW, PAT, FRAME, CIRC ou PITCHCIRC esperado</translation>
    </message>
    <message>
        <source>PATTERN DEF needs at least one pattern element</source>
        <translation>PATTERN DEF precisa de pelo menos um elemento de padrão</translation>
    </message>
    <message>
        <source>Spindle?</source>
        <translation>Mandril?</translation>
    </message>
    <message>
        <source>Tool axis is missing</source>
        <translation>Falta o eixo da ferramenta</translation>
    </message>
    <message>
        <source>Tool radius too small</source>
        <translation>Raio da ferramenta demasiado pequeno</translation>
    </message>
    <message>
        <source>Tool radius too large</source>
        <translation>Raio da ferramenta demasiado grande</translation>
    </message>
    <message>
        <source>Range exceeded</source>
        <translation>Campo excedido</translation>
    </message>
    <message>
        <source>Start position incorrect</source>
        <translation>Posição inicial incorreta</translation>
    </message>
    <message>
        <source>ROTATION not permitted</source>
        <translation>ROTAÇÃO não permitida</translation>
    </message>
    <message>
        <source>SCALING FACTOR not permitted</source>
        <translation>FATOR DE ESCALA não permitido</translation>
    </message>
    <message>
        <source>MIRROR IMAGE not permitted</source>
        <translation>ESPELHO não permitido</translation>
    </message>
    <message>
        <source>Datum shift not permitted</source>
        <translation>Deslocação do ponto zero não permitida</translation>
    </message>
    <message>
        <source>Feed rate is missing</source>
        <translation>Falta o avanço</translation>
    </message>
    <message>
        <source>Input value incorrect</source>
        <translation>Valor introduzido incorreto</translation>
    </message>
    <message>
        <source>Incorrect sign</source>
        <translation>Sinal incorreto</translation>
    </message>
    <message>
        <source>Entered angle not permitted</source>
        <translation>Ângulo introduzido não permitido</translation>
    </message>
    <message>
        <source>Touch point inaccessible</source>
        <translation>Ponto de apalpação inacessível</translation>
    </message>
    <message>
        <source>Too many points</source>
        <translation>Demasiados pontos</translation>
    </message>
    <message>
        <source>Contradictory input</source>
        <translation>Introdução contraditória</translation>
    </message>
    <message>
        <source>CYCL incomplete</source>
        <translation>CYCL incompleto</translation>
    </message>
    <message>
        <source>Plane wrongly defined</source>
        <translation>Plano mal definido</translation>
    </message>
    <message>
        <source>Wrong axis programmed</source>
        <translation>Eixo programado errado</translation>
    </message>
    <message>
        <source>Wrong RPM</source>
        <translation>Velocidade errada</translation>
    </message>
    <message>
        <source>Radius comp. undefined</source>
        <translation>Correção de raio indefinida</translation>
    </message>
    <message>
        <source>Rounding-off undefined</source>
        <translation>Arredondamento indefinido</translation>
    </message>
    <message>
        <source>Rounding radius too large</source>
        <translation>Raio de arredondamento demasiado grande</translation>
    </message>
    <message>
        <source>Program start undefined</source>
        <translation>Início do programa indefinido</translation>
    </message>
    <message>
        <source>Excessive nesting</source>
        <translation>Imbricação excessiva</translation>
    </message>
    <message>
        <source>Angle reference missing</source>
        <translation>Falta a referência angular</translation>
    </message>
    <message>
        <source>No fixed cycle defined</source>
        <translation>Nenhum ciclo fixo definido</translation>
    </message>
    <message>
        <source>Slot width too small</source>
        <translation>Largura da ranhura demasiado pequena</translation>
    </message>
    <message>
        <source>Pocket too small</source>
        <translation>Caixa demasiado pequena</translation>
    </message>
    <message>
        <source>Q202 not defined</source>
        <translation>Q202 não definido</translation>
    </message>
    <message>
        <source>Q205 not defined</source>
        <translation>Q205 não definido</translation>
    </message>
    <message>
        <source>Q218 must be greater than Q219</source>
        <translation>Q218 tem de ser maior que Q219</translation>
    </message>
    <message>
        <source>CYCL 210 not permitted</source>
        <translation>CYCL 210 não permitido</translation>
    </message>
    <message>
        <source>CYCL 211 not permitted</source>
        <translation>CYCL 211 não permitido</translation>
    </message>
    <message>
        <source>Q220 too large</source>
        <translation>Q220 demasiado grande</translation>
    </message>
    <message>
        <source>Q222 must be greater than Q223</source>
        <translation>Q222 tem de ser maior que Q223</translation>
    </message>
    <message>
        <source>Q244 must be greater than 0</source>
        <translation>Q244 tem de ser maior que 0</translation>
    </message>
    <message>
        <source>Q245 must not equal Q246</source>
        <translation>Q245 não pode ser igual a Q246</translation>
    </message>
    <message>
        <source>Angle range must be under 360 degrees</source>
        <translation>A gama angular tem de ser inferior a 360 graus</translation>
    </message>
    <message>
        <source>Q223 must be greater than Q222</source>
        <translation>Q223 tem de ser maior que Q222</translation>
    </message>
    <message>
        <source>Q214: 0 not permitted</source>
        <translation>Q214: 0 não permitido</translation>
    </message>
    <message>
        <source>Traverse direction not defined</source>
        <translation>Direção de deslocação não definida</translation>
    </message>
    <message>
        <source>No datum table active</source>
        <translation>Nenhuma tabela de pontos zero ativa</translation>
    </message>
    <message>
        <source>Position error: center in axis 1</source>
        <translation>Erro de posição: centro no eixo 1</translation>
    </message>
    <message>
        <source>Position error: center in axis 2</source>
        <translation>Erro de posição: centro no eixo 2</translation>
    </message>
    <message>
        <source>Hole diameter too small</source>
        <translation>Diâmetro do furo demasiado pequeno</translation>
    </message>
    <message>
        <source>Hole diameter too large</source>
        <translation>Diâmetro do furo demasiado grande</translation>
    </message>
    <message>
        <source>Stud diameter too small</source>
        <translation>Diâmetro da ilha demasiado pequeno</translation>
    </message>
    <message>
        <source>Stud diameter too large</source>
        <translation>Diâmetro da ilha demasiado grande</translation>
    </message>
    <message>
        <source>Pocket too small: rework axis 1</source>
        <translation>Caixa demasiado pequena: retrabalhar eixo 1</translation>
    </message>
    <message>
        <source>Pocket too small: rework axis 2</source>
        <translation>Caixa demasiado pequena: retrabalhar eixo 2</translation>
    </message>
    <message>
        <source>Pocket too large: scrap axis 1</source>
        <translation>Caixa demasiado grande: peça rejeitada eixo 1</translation>
    </message>
    <message>
        <source>Pocket too large: scrap axis 2</source>
        <translation>Caixa demasiado grande: peça rejeitada eixo 2</translation>
    </message>
    <message>
        <source>Stud too small: scrap axis 1</source>
        <translation>Ilha demasiado pequena: peça rejeitada eixo 1</translation>
    </message>
    <message>
        <source>Stud too small: scrap axis 2</source>
        <translation>Ilha demasiado pequena: peça rejeitada eixo 2</translation>
    </message>
    <message>
        <source>Stud too large: rework axis 1</source>
        <translation>Ilha demasiado grande: retrabalhar eixo 1</translation>
    </message>
    <message>
        <source>Stud too large: rework axis 2</source>
        <translation>Ilha demasiado grande: retrabalhar eixo 2</translation>
    </message>
    <message>
        <source>TCHPROBE 425: length exceeds max</source>
        <translation>TCHPROBE 425: comprimento acima do máximo</translation>
    </message>
    <message>
        <source>TCHPROBE 425: length below min</source>
        <translation>TCHPROBE 425: comprimento abaixo do mínimo</translation>
    </message>
    <message>
        <source>TCHPROBE 426: length exceeds max</source>
        <translation>TCHPROBE 426: comprimento acima do máximo</translation>
    </message>
    <message>
        <source>TCHPROBE 426: length below min</source>
        <translation>TCHPROBE 426: comprimento abaixo do mínimo</translation>
    </message>
    <message>
        <source>TCHPROBE 430: diameter too large</source>
        <translation>TCHPROBE 430: diâmetro demasiado grande</translation>
    </message>
    <message>
        <source>TCHPROBE 430: diameter too small</source>
        <translation>TCHPROBE 430: diâmetro demasiado pequeno</translation>
    </message>
    <message>
        <source>No measuring axis defined</source>
        <translation>Nenhum eixo de medição definido</translation>
    </message>
    <message>
        <source>Tool breakage tolerance exceeded</source>
        <translation>Tolerância de rotura da ferramenta excedida</translation>
    </message>
    <message>
        <source>Enter Q247 unequal 0</source>
        <translation>Introduzir Q247 diferente de 0</translation>
    </message>
    <message>
        <source>Enter Q247 greater than 5</source>
        <translation>Introduzir Q247 maior que 5</translation>
    </message>
    <message>
        <source>Datum table?</source>
        <translation>Tabela de pontos zero?</translation>
    </message>
    <message>
        <source>Enter Q351 unequal 0</source>
        <translation>Introduzir Q351 diferente de 0</translation>
    </message>
    <message>
        <source>Thread depth too large</source>
        <translation>Profundidade da rosca demasiado grande</translation>
    </message>
    <message>
        <source>Missing calibration data</source>
        <translation>Faltam dados de calibração</translation>
    </message>
    <message>
        <source>Tolerance exceeded</source>
        <translation>Tolerância excedida</translation>
    </message>
    <message>
        <source>Block scan active</source>
        <translation>Avanço até ao bloco ativo</translation>
    </message>
    <message>
        <source>ORIENTATION not permitted</source>
        <translation>ORIENTAÇÃO não permitida</translation>
    </message>
    <message>
        <source>3DROT not permitted</source>
        <translation>3DROT não permitido</translation>
    </message>
    <message>
        <source>Activate 3DROT</source>
        <translation>Ativar 3DROT</translation>
    </message>
    <message>
        <source>Enter depth as negative</source>
        <translation>Introduzir a profundidade com sinal negativo</translation>
    </message>
    <message>
        <source>Q303 not defined in measuring cycle</source>
        <translation>Q303 não definido no ciclo de medição</translation>
    </message>
    <message>
        <source>Tool axis not allowed</source>
        <translation>Eixo da ferramenta não permitido</translation>
    </message>
    <message>
        <source>Calculated values incorrect</source>
        <translation>Valores calculados incorretos</translation>
    </message>
    <message>
        <source>Contradictory measuring points</source>
        <translation>Pontos de medição contraditórios</translation>
    </message>
    <message>
        <source>Incorrect clearance height</source>
        <translation>Altura segura incorreta</translation>
    </message>
    <message>
        <source>Contradictory plunge type</source>
        <translation>Tipo de penetração contraditório</translation>
    </message>
    <message>
        <source>This fixed cycle not allowed</source>
        <translation>Este ciclo fixo não é permitido</translation>
    </message>
    <message>
        <source>Line is write-protected</source>
        <translation>Linha protegida contra escrita</translation>
    </message>
    <message>
        <source>Oversize greater than depth</source>
        <translation>Sobre-medida maior que a profundidade</translation>
    </message>
    <message>
        <source>No point angle defined</source>
        <translation>Nenhum ângulo da ponta definido</translation>
    </message>
    <message>
        <source>Contradictory data</source>
        <translation>Dados contraditórios</translation>
    </message>
    <message>
        <source>Slot position 0 not allowed</source>
        <translation>Posição da ranhura 0 não permitida</translation>
    </message>
    <message>
        <source>Enter an infeed not equal to 0</source>
        <translation>Introduzir um passo diferente de 0</translation>
    </message>
    <message>
        <source>{1} is not defined for this value</source>
        <translation>{1} não está definido para este valor</translation>
    </message>
    <message>
        <source>a string parameter cannot be used as a number</source>
        <translation>um parâmetro de texto não pode ser usado como número</translation>
    </message>
    <message>
        <source>{1}{2} does not exist (0 to {3})</source>
        <translation>{1}{2} não existe (0 a {3})</translation>
    </message>
    <message>
        <source>number or Q parameter expected</source>
        <translation>número ou parâmetro Q esperado</translation>
    </message>
    <message>
        <source>incomplete formula</source>
        <translation>fórmula incompleta</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in formula</source>
        <translation>&apos;{1}&apos; inesperado na fórmula</translation>
    </message>
    <message>
        <source>string parameter QS expected</source>
        <translation>parâmetro de texto QS esperado</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a number</source>
        <translation>&apos;{1}&apos; não é um número</translation>
    </message>
    <message>
        <source>&apos;||&apos; expected</source>
        <translation>&apos;||&apos; esperado</translation>
    </message>
    <message>
        <source>SUBSTR needs BEG and LEN of at least 0</source>
        <translation>SUBSTR precisa de BEG e LEN de pelo menos 0</translation>
    </message>
    <message>
        <source>SYSSTR ID{1} NR{2} is not available</source>
        <translation>SYSSTR ID{1} NR{2} não está disponível</translation>
    </message>
    <message>
        <source>string expected</source>
        <translation>texto esperado</translation>
    </message>
    <message>
        <source>unknown keyword &apos;{1}&apos;</source>
        <translation>palavra-chave desconhecida &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>the format has no closing quote</source>
        <translation>o formato não tem aspa de fecho</translation>
    </message>
    <message>
        <source>unknown value &apos;{1}&apos;</source>
        <translation>valor desconhecido &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>bad format field</source>
        <translation>campo de formato inválido</translation>
    </message>
    <message>
        <source>more fields than values</source>
        <translation>mais campos do que valores</translation>
    </message>
    <message>
        <source>a cycle cannot be called with radius compensation RL/RR: program R0</source>
        <translation>um ciclo não pode ser chamado com correção de raio RL/RR: programe R0</translation>
    </message>
    <message>
        <source>the cycle calls of this block need more than {1} moves</source>
        <translation>as chamadas de ciclo deste bloco precisam de mais de {1} movimentos</translation>
    </message>
    <message>
        <source>no machining cycle is defined (CYCL DEF)</source>
        <translation>nenhum ciclo de maquinagem definido (CYCL DEF)</translation>
    </message>
    <message>
        <source>CYCL CALL PAT: no PATTERN DEF or point table (SEL PATTERN) is active</source>
        <translation>CYCL CALL PAT: nenhum PATTERN DEF nem tabela de pontos (SEL PATTERN) ativo</translation>
    </message>
    <message>
        <source>CYCL CALL PAT cannot use FMAX (without F it moves at rapid)</source>
        <translation>CYCL CALL PAT não pode usar FMAX (sem F desloca-se em marcha rápida)</translation>
    </message>
    <message>
        <source>CYCL CALL POS needs all three coordinates</source>
        <translation>CYCL CALL POS precisa das três coordenadas</translation>
    </message>
    <message>
        <source>cycle {1} needs a machining cycle defined before it</source>
        <translation>o ciclo {1} precisa de um ciclo de maquinagem definido antes dele</translation>
    </message>
    <message>
        <source>cycle {1} cannot call cycle {2}</source>
        <translation>o ciclo {1} não pode chamar o ciclo {2}</translation>
    </message>
    <message>
        <source>{1} has no parameter Q{2}: it is ignored</source>
        <translation>{1} não tem o parâmetro Q{2}: é ignorado</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) is missing</source>
        <translation>{1}: falta o parâmetro {2} ({3})</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) needs a text in quotes or a QS parameter</source>
        <translation>{1}: o parâmetro {2} ({3}) precisa de um texto entre aspas ou de um parâmetro QS</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) does not accept {4}</source>
        <translation>{1}: o parâmetro {2} ({3}) não aceita {4}</translation>
    </message>
    <message>
        <source>FAUTO: the TOOL CALL block gave no feed rate F</source>
        <translation>FAUTO: o bloco TOOL CALL não deu avanço F</translation>
    </message>
    <message>
        <source>{1}: {2} needs a feed value after {3}</source>
        <translation>{1}: {2} precisa de um valor de avanço depois de {3}</translation>
    </message>
    <message>
        <source>FZ needs the number of teeth (CUT) of the tool</source>
        <translation>FZ precisa do número de lâminas (CUT) da ferramenta</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = &apos;{4}&apos; is not a value</source>
        <translation>{1}: o parâmetro {2} ({3}) = &apos;{4}&apos; não é um valor</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = {4} must be a whole number from {5} to {6}</source>
        <translation>{1}: o parâmetro {2} ({3}) = {4} tem de ser um número inteiro de {5} a {6}</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) = {4} is outside {5} to {6}</source>
        <translation>{1}: o parâmetro {2} ({3}) = {4} está fora de {5} a {6}</translation>
    </message>
    <message>
        <source>cycle {1} is not supported yet</source>
        <translation>o ciclo {1} ainda não é suportado</translation>
    </message>
    <message>
        <source>CYCL DEF {1}.{2} without CYCL DEF {1}.0 before it</source>
        <translation>CYCL DEF {1}.{2} sem CYCL DEF {1}.0 antes</translation>
    </message>
    <message>
        <source>GLOBAL DEF {1} does not exist</source>
        <translation>GLOBAL DEF {1} não existe</translation>
    </message>
    <message>
        <source>cannot read the datum table {1}: {2}</source>
        <translation>não é possível ler a tabela de pontos zero {1}: {2}</translation>
    </message>
    <message>
        <source>cannot read the point table {1}: {2}</source>
        <translation>não é possível ler a tabela de pontos {1}: {2}</translation>
    </message>
    <message>
        <source>{1} is not supported yet</source>
        <translation>{1} ainda não é suportado</translation>
    </message>
    <message>
        <source>FN 14 error {1}: {2}</source>
        <translation>FN 14 erro {1}: {2}</translation>
    </message>
    <message>
        <source>FN 14 error {1}</source>
        <translation>FN 14 erro {1}</translation>
    </message>
    <message>
        <source>cannot read the F-PRINT mask {1}</source>
        <translation>não é possível ler a máscara F-PRINT {1}</translation>
    </message>
    <message>
        <source>F-PRINT mask {1} has an error</source>
        <translation>a máscara F-PRINT {1} tem um erro</translation>
    </message>
    <message>
        <source>cannot write {1}</source>
        <translation>não é possível escrever {1}</translation>
    </message>
    <message>
        <source>FN 18: SYSREAD ID{1} NR{2} IDX{3} is not available</source>
        <translation>FN 18: SYSREAD ID{1} NR{2} IDX{3} não está disponível</translation>
    </message>
    <message>
        <source>FN {1}: the points do not define a circle</source>
        <translation>FN {1}: os pontos não definem um círculo</translation>
    </message>
    <message>
        <source>FN 26: cannot open table {1}</source>
        <translation>FN 26: não é possível abrir a tabela {1}</translation>
    </message>
    <message>
        <source>no table is open (FN 26: TABOPEN)</source>
        <translation>nenhuma tabela aberta (FN 26: TABOPEN)</translation>
    </message>
    <message>
        <source>FN 27: cannot write row {1}</source>
        <translation>FN 27: não é possível escrever a linha {1}</translation>
    </message>
    <message>
        <source>FN 28: cannot read row {1}</source>
        <translation>FN 28: não é possível ler a linha {1}</translation>
    </message>
    <message>
        <source>cannot read the program: {1}</source>
        <translation>não é possível ler o programa: {1}</translation>
    </message>
    <message>
        <source>label {1} is not defined</source>
        <translation>o label {1} não está definido</translation>
    </message>
    <message>
        <source>subprograms nested deeper than {1} levels</source>
        <translation>subprogramas imbricados em mais de {1} níveis</translation>
    </message>
    <message>
        <source>program calls nested deeper than {1} levels</source>
        <translation>chamadas de programa imbricadas em mais de {1} níveis</translation>
    </message>
    <message>
        <source>cannot call program {1}: {2}</source>
        <translation>não é possível chamar o programa {1}: {2}</translation>
    </message>
    <message>
        <source>the called program {1} has errors</source>
        <translation>o programa chamado {1} tem erros</translation>
    </message>
    <message>
        <source>feed rate is missing</source>
        <translation>falta o avanço</translation>
    </message>
    <message>
        <source>M140 MB MAX: the tool axis has no limit</source>
        <translation>M140 MB MAX: o eixo da ferramenta não tem limite</translation>
    </message>
    <message>
        <source>tool {1} is not in the tool table</source>
        <translation>a ferramenta {1} não está na tabela de ferramentas</translation>
    </message>
    <message>
        <source>no tool table: tool {1} and the following tools are used with length 0 and radius 0</source>
        <translation>sem tabela de ferramentas: a ferramenta {1} e as seguintes são usadas com comprimento 0 e raio 0</translation>
    </message>
    <message>
        <source>tool {1} is locked (TL)</source>
        <translation>a ferramenta {1} está bloqueada (TL)</translation>
    </message>
    <message>
        <source>spindle speed {1} exceeds the machine&apos;s {2} rpm</source>
        <translation>a velocidade do mandril {1} excede as {2} rpm da máquina</translation>
    </message>
    <message>
        <source>BLK FORM 0.2 needs BLK FORM 0.1 before it</source>
        <translation>BLK FORM 0.2 precisa de BLK FORM 0.1 antes</translation>
    </message>
    <message>
        <source>the blank has no volume</source>
        <translation>o bloco não tem volume</translation>
    </message>
    <message>
        <source>CC axes {1} and {2} do not span a plane</source>
        <translation>os eixos de CC {1} e {2} não formam um plano</translation>
    </message>
    <message>
        <source>CC takes two coordinates of a plane</source>
        <translation>CC leva duas coordenadas de um plano</translation>
    </message>
    <message>
        <source>circular moves cannot use FMAX</source>
        <translation>movimentos circulares não podem usar FMAX</translation>
    </message>
    <message>
        <source>direction of rotation DR+ or DR- missing</source>
        <translation>falta o sentido de rotação DR+ ou DR-</translation>
    </message>
    <message>
        <source>no circle of radius {1} passes through the start and end point</source>
        <translation>nenhum círculo de raio {1} passa pelo ponto inicial e final</translation>
    </message>
    <message>
        <source>circle centre CC is not defined</source>
        <translation>o centro do círculo CC não está definido</translation>
    </message>
    <message>
        <source>the end point is not on the circle: radius {1} at the start, {2} at the end</source>
        <translation>o ponto final não está no círculo: raio {1} no início, {2} no fim</translation>
    </message>
    <message>
        <source>a tangential arc needs a contour element before it</source>
        <translation>um arco tangencial precisa de um elemento de contorno antes</translation>
    </message>
    <message>
        <source>pole CC is not defined</source>
        <translation>o polo CC não está definido</translation>
    </message>
    <message>
        <source>the end point lies on the tangent: no arc possible</source>
        <translation>o ponto final está na tangente: arco impossível</translation>
    </message>
    <message>
        <source>CP needs a polar angle PA or IPA</source>
        <translation>CP precisa de um ângulo polar PA ou IPA</translation>
    </message>
    <message>
        <source>the sign of IPA does not match DR</source>
        <translation>o sinal de IPA não corresponde a DR</translation>
    </message>
    <message>
        <source>{1} needs a positive length LEN</source>
        <translation>{1} precisa de um comprimento LEN positivo</translation>
    </message>
    <message>
        <source>{1} CT needs an angle CCA (0 to 360) and a radius R</source>
        <translation>{1} CT precisa de um ângulo CCA (0 a 360) e de um raio R</translation>
    </message>
    <message>
        <source>{1} LCT needs a radius R</source>
        <translation>{1} LCT precisa de um raio R</translation>
    </message>
    <message>
        <source>APPR needs radius compensation RL or RR</source>
        <translation>APPR precisa de correção de raio RL ou RR</translation>
    </message>
    <message>
        <source>DEP LCT needs the end point</source>
        <translation>DEP LCT precisa do ponto final</translation>
    </message>
    <message>
        <source>an arc in the {1} plane cannot be rotated out of its plane or scaled with different factors</source>
        <translation>um arco no plano {1} não pode ser rodado para fora do seu plano nem escalado com fatores diferentes</translation>
    </message>
    <message>
        <source>cycle 7: no datum table selected (SEL TABLE)</source>
        <translation>ciclo 7: nenhuma tabela de pontos zero selecionada (SEL TABLE)</translation>
    </message>
    <message>
        <source>cycle 7: datum {1} is not in the datum table</source>
        <translation>ciclo 7: o ponto zero {1} não está na tabela de pontos zero</translation>
    </message>
    <message>
        <source>cycle 8: the tool axis {1} cannot be mirrored; it is left out</source>
        <translation>ciclo 8: o eixo da ferramenta {1} não pode ser espelhado; é omitido</translation>
    </message>
    <message>
        <source>cycle 247: no preset table (PRESET.PR) to read preset {1} from</source>
        <translation>ciclo 247: nenhuma tabela de pontos de referência (PRESET.PR) para ler o ponto de referência {1}</translation>
    </message>
    <message>
        <source>cycle 247: preset {1} is not in the preset table</source>
        <translation>ciclo 247: o ponto de referência {1} não está na tabela de pontos de referência</translation>
    </message>
    <message>
        <source>cycle {1}: {2} expected</source>
        <translation>ciclo {1}: {2} esperado</translation>
    </message>
    <message>
        <source>cycle 12: program name expected</source>
        <translation>ciclo 12: nome de programa esperado</translation>
    </message>
    <message>
        <source>cycle 18 has no sub-block 18.{1}</source>
        <translation>o ciclo 18 não tem o sub-bloco 18.{1}</translation>
    </message>
    <message>
        <source>cycle 32: unexpected &apos;{1}&apos;</source>
        <translation>ciclo 32: &apos;{1}&apos; inesperado</translation>
    </message>
    <message>
        <source>block number {1} is out of order (after {2})</source>
        <translation>o número de bloco {1} está fora de ordem (depois de {2})</translation>
    </message>
    <message>
        <source>BEGIN PGM must be the first block</source>
        <translation>BEGIN PGM tem de ser o primeiro bloco</translation>
    </message>
    <message>
        <source>END PGM {1} does not match BEGIN PGM {2}</source>
        <translation>END PGM {1} não corresponde a BEGIN PGM {2}</translation>
    </message>
    <message>
        <source>label {1} is defined twice</source>
        <translation>o label {1} está definido duas vezes</translation>
    </message>
    <message>
        <source>{1} is not supported yet; the program cannot run past this block</source>
        <translation>{1} ainda não é suportado; o programa não pode continuar para além deste bloco</translation>
    </message>
    <message>
        <source>cycle {1} is not supported yet; the program cannot run past this block</source>
        <translation>o ciclo {1} ainda não é suportado; o programa não pode continuar para além deste bloco</translation>
    </message>
    <message>
        <source>block has no number while others have</source>
        <translation>o bloco não tem número enquanto outros têm</translation>
    </message>
    <message>
        <source>the program has no BEGIN PGM block</source>
        <translation>o programa não tem bloco BEGIN PGM</translation>
    </message>
    <message>
        <source>the program has no END PGM block</source>
        <translation>o programa não tem bloco END PGM</translation>
    </message>
    <message>
        <source>expected QRn=value</source>
        <translation>esperado QRn=valor</translation>
    </message>
    <message>
        <source>a rounding or chamfer must be followed by a contour element in the working plane</source>
        <translation>um arredondamento ou chanfre tem de ser seguido de um elemento de contorno no plano de maquinagem</translation>
    </message>
    <message>
        <source>a chamfer needs straight lines on both sides</source>
        <translation>um chanfre precisa de retas de ambos os lados</translation>
    </message>
    <message>
        <source>the chamfer is longer than the adjacent element</source>
        <translation>o chanfre é mais comprido que o elemento adjacente</translation>
    </message>
    <message>
        <source>the rounding radius does not fit between the elements</source>
        <translation>o raio de arredondamento não cabe entre os elementos</translation>
    </message>
    <message>
        <source>a rounding needs a contour element before it</source>
        <translation>um arredondamento precisa de um elemento de contorno antes</translation>
    </message>
    <message>
        <source>a chamfer needs a contour element before it</source>
        <translation>um chanfre precisa de um elemento de contorno antes</translation>
    </message>
    <message>
        <source>a rounding or chamfer must be followed by a contour element</source>
        <translation>um arredondamento ou chanfre tem de ser seguido de um elemento de contorno</translation>
    </message>
    <message>
        <source>an approach must be followed by a compensated contour element</source>
        <translation>uma aproximação tem de ser seguida de um elemento de contorno corrigido</translation>
    </message>
    <message>
        <source>an approach needs RL or RR</source>
        <translation>uma aproximação precisa de RL ou RR</translation>
    </message>
    <message>
        <source>a departure needs a compensated contour element before it</source>
        <translation>uma saída precisa de um elemento de contorno corrigido antes</translation>
    </message>
    <message>
        <source>the departure cannot be constructed with these values</source>
        <translation>a saída não pode ser construída com estes valores</translation>
    </message>
    <message>
        <source>leave radius compensation with a straight line</source>
        <translation>termine a correção de raio com uma reta</translation>
    </message>
    <message>
        <source>switching between RL and RR needs a block with R0 between</source>
        <translation>mudar entre RL e RR precisa de um bloco com R0 no meio</translation>
    </message>
    <message>
        <source>radius compensation must begin with a straight line</source>
        <translation>a correção de raio tem de começar com uma reta</translation>
    </message>
    <message>
        <source>the approach cannot be constructed with these values</source>
        <translation>a aproximação não pode ser construída com estes valores</translation>
    </message>
    <message>
        <source>base = {1} is not a built-in machine ({2})</source>
        <translation>base = {1} não é uma máquina incorporada ({2})</translation>
    </message>
    <message>
        <source>{1} must be a table</source>
        <translation>{1} tem de ser uma tabela</translation>
    </message>
    <message>
        <source>axes must be a table of axes such as [axes.X]</source>
        <translation>axes tem de ser uma tabela de eixos como [axes.X]</translation>
    </message>
    <message>
        <source>{1}: {2} is not an axis letter; use one of {3}</source>
        <translation>{1}: {2} não é uma letra de eixo; use uma de {3}</translation>
    </message>
    <message>
        <source>{1} is a table; expected {2}</source>
        <translation>{1} é uma tabela; esperado {2}</translation>
    </message>
    <message>
        <source>{1} = {2} is {3}; expected {4}</source>
        <translation>{1} = {2} é {3}; esperado {4}</translation>
    </message>
    <message>
        <source>unknown key {1}</source>
        <translation>chave desconhecida {1}</translation>
    </message>
    <message>
        <source>unknown key {1}; did you mean {2}?</source>
        <translation>chave desconhecida {1}; queria dizer {2}?</translation>
    </message>
    <message>
        <source>TOML syntax error: {1}</source>
        <translation>erro de sintaxe TOML: {1}</translation>
    </message>
    <message>
        <source>cannot read the machine configuration: {1}</source>
        <translation>não é possível ler a configuração da máquina: {1}</translation>
    </message>
    <message>
        <source>Name shown to the operator</source>
        <translation>Nome mostrado ao operador</translation>
    </message>
    <message>
        <source>Machine kind; selects the program dialects and lathe conventions</source>
        <translation>Tipo de máquina; seleciona os dialetos de programa e as convenções de torno</translation>
    </message>
    <message>
        <source>Axis the tool points along; tool length compensation acts on it</source>
        <translation>Eixo segundo o qual a ferramenta aponta; a correção do comprimento da ferramenta atua nele</translation>
    </message>
    <message>
        <source>Path velocity of rapid moves</source>
        <translation>Velocidade de trajetória dos movimentos rápidos</translation>
    </message>
    <message>
        <source>Highest programmable feed rate</source>
        <translation>Avanço programável máximo</translation>
    </message>
    <message>
        <source>Period of the servo cycle</source>
        <translation>Período do ciclo de servo</translation>
    </message>
    <message>
        <source>Default path deviation allowed when blending corners; 0 stops exactly</source>
        <translation>Desvio de trajetória admitido por defeito ao arredondar esquinas; 0 para com exatidão</translation>
    </message>
    <message>
        <source>Lowest spindle speed</source>
        <translation>Velocidade mínima do mandril</translation>
    </message>
    <message>
        <source>Highest spindle speed</source>
        <translation>Velocidade máxima do mandril</translation>
    </message>
    <message>
        <source>CANopen node-ID of the spindle drive; 0: the spindle has none</source>
        <translation>Node-ID CANopen do acionamento do mandril; 0: o mandril não tem</translation>
    </message>
    <message>
        <source>Spindle drive position units per degree</source>
        <translation>Unidades de posição do acionamento do mandril por grau</translation>
    </message>
    <message>
        <source>CiA 402 mode of the spindle drive: cyclic synchronous or profile velocity</source>
        <translation>Modo CiA 402 do acionamento do mandril: síncrono cíclico ou velocidade de perfil</translation>
    </message>
    <message>
        <source>Lathe: diameter of the bar simulated when the program defines no blank; 0: none</source>
        <translation>Torno: diâmetro da barra simulada quando o programa não define bloco; 0: nenhuma</translation>
    </message>
    <message>
        <source>Lathe: length of the simulated bar</source>
        <translation>Torno: comprimento da barra simulada</translation>
    </message>
    <message>
        <source>Lathe: workpiece Z of the bar&apos;s face; the bar reaches down to face_z - length</source>
        <translation>Torno: Z da peça na face da barra; a barra vai até face_z - length</translation>
    </message>
    <message>
        <source>Lathe: inner diameter of a tube; 0: a solid bar</source>
        <translation>Torno: diâmetro interior de um tubo; 0: uma barra maciça</translation>
    </message>
    <message>
        <source>SocketCAN interface of the drive bus</source>
        <translation>Interface SocketCAN do barramento dos acionamentos</translation>
    </message>
    <message>
        <source>Bit rate of the drive bus (a CiA 301 rate)</source>
        <translation>Taxa de bits do barramento dos acionamentos (uma taxa CiA 301)</translation>
    </message>
    <message>
        <source>SYNC period of the drive bus; a whole multiple of servo_period</source>
        <translation>Período SYNC do barramento dos acionamentos; múltiplo inteiro de servo_period</translation>
    </message>
    <message>
        <source>Heartbeat period of every drive (0x1017)</source>
        <translation>Período de heartbeat de cada acionamento (0x1017)</translation>
    </message>
    <message>
        <source>A drive whose heartbeat is missing this long is lost; above heartbeat_period</source>
        <translation>Um acionamento cujo heartbeat falta durante este tempo está perdido; acima de heartbeat_period</translation>
    </message>
    <message>
        <source>A drive whose feedback PDO is missing this many cycles is lost</source>
        <translation>Um acionamento cujo PDO de retorno falta durante este número de ciclos está perdido</translation>
    </message>
    <message>
        <source>CANopen node-ID of the control&apos;s heartbeat, watched by the drives</source>
        <translation>Node-ID CANopen do heartbeat do comando, vigiado pelos acionamentos</translation>
    </message>
    <message>
        <source>Vendor-ID every drive must report (0x1018 sub 1), hexadecimal like 0x0000029C; empty: not checked</source>
        <translation>Vendor-ID que cada acionamento tem de indicar (0x1018 sub 1), hexadecimal como 0x0000029C; vazio: não verificado</translation>
    </message>
    <message>
        <source>Product code every drive must report (0x1018 sub 2); empty: not checked</source>
        <translation>Código de produto que cada acionamento tem de indicar (0x1018 sub 2); vazio: não verificado</translation>
    </message>
    <message>
        <source>Linear or rotary; A, B and C default to rotary</source>
        <translation>Linear ou rotativo; A, B e C são rotativos por defeito</translation>
    </message>
    <message>
        <source>Lower soft limit in machine coordinates (a radius on a lathe)</source>
        <translation>Limite de software inferior em coordenadas de máquina (um raio num torno)</translation>
    </message>
    <message>
        <source>Upper soft limit in machine coordinates (a radius on a lathe)</source>
        <translation>Limite de software superior em coordenadas de máquina (um raio num torno)</translation>
    </message>
    <message>
        <source>Highest velocity of the axis</source>
        <translation>Velocidade máxima do eixo</translation>
    </message>
    <message>
        <source>Highest acceleration of the axis</source>
        <translation>Aceleração máxima do eixo</translation>
    </message>
    <message>
        <source>Highest jerk of the axis</source>
        <translation>Sobreaceleração (jerk) máxima do eixo</translation>
    </message>
    <message>
        <source>Machine position after homing; must lie within the soft limits</source>
        <translation>Posição de máquina depois da referenciação; tem de estar dentro dos limites de software</translation>
    </message>
    <message>
        <source>The axis may be absent and is then switched off with enabled = false</source>
        <translation>O eixo pode faltar e é então desligado com enabled = false</translation>
    </message>
    <message>
        <source>The axis is present; only optional axes may be disabled</source>
        <translation>O eixo está presente; só os eixos opcionais podem ser desativados</translation>
    </message>
    <message>
        <source>Lathe: the axis is programmed and displayed as a diameter</source>
        <translation>Torno: o eixo é programado e visualizado como diâmetro</translation>
    </message>
    <message>
        <source>CANopen node-ID of the axis drive; 0: none</source>
        <translation>Node-ID CANopen do acionamento do eixo; 0: nenhum</translation>
    </message>
    <message>
        <source>Drive position units per millimetre or degree</source>
        <translation>Unidades de posição do acionamento por milímetro ou grau</translation>
    </message>
    <message>
        <source>Following error the drive allows (0x6065) before it faults</source>
        <translation>Erro de seguimento que o acionamento admite (0x6065) antes de entrar em falha</translation>
    </message>
    <message>
        <source>the machine has no axis for {1}</source>
        <translation>a máquina não tem eixo para {1}</translation>
    </message>
    <message>
        <source>{1} = {2} must be less than {3} = {4}</source>
        <translation>{1} = {2} tem de ser menor que {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the soft limits {3} … {4} {5}</source>
        <translation>{1} = {2} está fora dos limites de software {3} … {4} {5}</translation>
    </message>
    <message>
        <source>{1} = false is only allowed when {2} = true</source>
        <translation>{1} = false só é permitido quando {2} = true</translation>
    </message>
    <message>
        <source>{1} = true is only allowed on a linear axis of a lathe</source>
        <translation>{1} = true só é permitido num eixo linear de um torno</translation>
    </message>
    <message>
        <source>the machine has no axes; add [axes.X] tables or start from a built-in machine with base = &quot;mill&quot;</source>
        <translation>a máquina não tem eixos; acrescente tabelas [axes.X] ou parta de uma máquina incorporada com base = &quot;mill&quot;</translation>
    </message>
    <message>
        <source>axis letter {1} is not one of {2}</source>
        <translation>a letra de eixo {1} não é uma de {2}</translation>
    </message>
    <message>
        <source>axis {1} is listed twice</source>
        <translation>o eixo {1} está listado duas vezes</translation>
    </message>
    <message>
        <source>tool_axis = {1} is not an enabled axis of this machine ({2})</source>
        <translation>tool_axis = {1} não é um eixo ativo desta máquina ({2})</translation>
    </message>
    <message>
        <source>tool_axis = {1} must be a linear axis</source>
        <translation>tool_axis = {1} tem de ser um eixo linear</translation>
    </message>
    <message>
        <source>{1} = {2} must not exceed {3} = {4}</source>
        <translation>{1} = {2} não pode exceder {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} must be smaller than {3} = {4}</source>
        <translation>{1} = {2} tem de ser menor que {3} = {4}</translation>
    </message>
    <message>
        <source>{1} = {2} is the node-ID of drives.master_node</source>
        <translation>{1} = {2} é o node-ID de drives.master_node</translation>
    </message>
    <message>
        <source>{1} = {2} is already the node of {3}</source>
        <translation>{1} = {2} já é o nó de {3}</translation>
    </message>
    <message>
        <source>drives.cycle_period = {1} must be a whole multiple of servo_period = {2}</source>
        <translation>drives.cycle_period = {1} tem de ser um múltiplo inteiro de servo_period = {2}</translation>
    </message>
    <message>
        <source>drives.heartbeat_timeout = {1} must exceed drives.heartbeat_period = {2}</source>
        <translation>drives.heartbeat_timeout = {1} tem de exceder drives.heartbeat_period = {2}</translation>
    </message>
    <message>
        <source>drives.bitrate = {1} is not a CiA 301 bit rate (10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)</source>
        <translation>drives.bitrate = {1} não é uma taxa de bits CiA 301 (10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)</translation>
    </message>
    <message>
        <source>{1} = &quot;{2}&quot; is not a 32-bit number such as 0x0000029C</source>
        <translation>{1} = &quot;{2}&quot; não é um número de 32 bits como 0x0000029C</translation>
    </message>
    <message>
        <source>{1} = {2} has the wrong type; expected {3}</source>
        <translation>{1} = {2} tem o tipo errado; esperado {3}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the allowed range {3}</source>
        <translation>{1} = {2} está fora da gama permitida {3}</translation>
    </message>
    <message>
        <source>{1} = {2} is not one of {3}</source>
        <translation>{1} = {2} não é um de {3}</translation>
    </message>
    <message>
        <source>empty file name</source>
        <translation>nome de ficheiro vazio</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is outside the NC root</source>
        <translation>&apos;{1}&apos; está fora da raiz NC</translation>
    </message>
    <message>
        <source>datum {1} is not in the datum table</source>
        <translation>o ponto zero {1} não está na tabela de pontos zero</translation>
    </message>
    <message>
        <source>datum {1} is already in the datum table</source>
        <translation>o ponto zero {1} já está na tabela de pontos zero</translation>
    </message>
    <message>
        <source>the table does not start with a BEGIN line</source>
        <translation>a tabela não começa com uma linha BEGIN</translation>
    </message>
    <message>
        <source>the BEGIN line names no table</source>
        <translation>a linha BEGIN não indica nenhuma tabela</translation>
    </message>
    <message>
        <source>the BEGIN line gives no file type</source>
        <translation>a linha BEGIN não indica o tipo de ficheiro</translation>
    </message>
    <message>
        <source>the table has no column {1}</source>
        <translation>a tabela não tem a coluna {1}</translation>
    </message>
    <message>
        <source>column {1} needs a whole number &gt;= 0, not &quot;{2}&quot;</source>
        <translation>a coluna {1} precisa de um número inteiro &gt;= 0, não &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>the table has no row {1}</source>
        <translation>a tabela não tem a linha {1}</translation>
    </message>
    <message>
        <source>the table has no column &quot;{1}&quot;</source>
        <translation>a tabela não tem a coluna &quot;{1}&quot;</translation>
    </message>
    <message>
        <source>cell {1} of row {2} is empty</source>
        <translation>a célula {1} da linha {2} está vazia</translation>
    </message>
    <message>
        <source>column {1} needs a number, not &quot;{2}&quot;</source>
        <translation>a coluna {1} precisa de um número, não &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>{1} columns named but {2} values given</source>
        <translation>{1} colunas indicadas mas {2} valores dados</translation>
    </message>
    <message>
        <source>column {1} holds text, not numbers</source>
        <translation>a coluna {1} contém texto, não números</translation>
    </message>
    <message>
        <source>point {1} is not in the point table</source>
        <translation>o ponto {1} não está na tabela de pontos</translation>
    </message>
    <message>
        <source>column {1} needs Y or nothing, not &quot;{2}&quot;</source>
        <translation>a coluna {1} precisa de Y ou nada, não &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>point {1} is already in the point table</source>
        <translation>o ponto {1} já está na tabela de pontos</translation>
    </message>
    <message>
        <source>preset {1} is not in the preset table</source>
        <translation>o ponto de referência {1} não está na tabela de pontos de referência</translation>
    </message>
    <message>
        <source>preset {1} is already in the preset table</source>
        <translation>o ponto de referência {1} já está na tabela de pontos de referência</translation>
    </message>
    <message>
        <source>column {1} needs a whole number, not &quot;{2}&quot;</source>
        <translation>a coluna {1} precisa de um número inteiro, não &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>the key column {1} is empty</source>
        <translation>a coluna chave {1} está vazia</translation>
    </message>
    <message>
        <source>{1} {2} appears twice (first in line {3})</source>
        <translation>{1} {2} aparece duas vezes (primeiro na linha {3})</translation>
    </message>
    <message>
        <source>the table has no column header line</source>
        <translation>a tabela não tem linha de cabeçalho das colunas</translation>
    </message>
    <message>
        <source>the table has no cell at row {1}, column {2}</source>
        <translation>a tabela não tem célula na linha {1}, coluna {2}</translation>
    </message>
    <message>
        <source>a cell of column {1} cannot hold a line break</source>
        <translation>uma célula da coluna {1} não pode conter uma quebra de linha</translation>
    </message>
    <message>
        <source>{2} does not fit into column {1} ({3} characters)</source>
        <translation>{2} não cabe na coluna {1} ({3} caracteres)</translation>
    </message>
    <message>
        <source>column {1} cannot hold an infinite number</source>
        <translation>a coluna {1} não pode conter um número infinito</translation>
    </message>
    <message>
        <source>cannot insert a row at {1}: the table has {2} rows</source>
        <translation>não é possível inserir uma linha em {1}: a tabela tem {2} linhas</translation>
    </message>
    <message>
        <source>&quot;{2}&quot; cannot be a key of column {1}</source>
        <translation>&quot;{2}&quot; não pode ser uma chave da coluna {1}</translation>
    </message>
    <message>
        <source>column {1} needs L, 1, 0 or nothing, not &quot;{2}&quot;</source>
        <translation>a coluna {1} precisa de L, 1, 0 ou nada, não &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>tool {1} is already in the tool table</source>
        <translation>a ferramenta {1} já está na tabela de ferramentas</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>inativo</translation>
    </message>
    <message>
        <source>running</source>
        <translation>em execução</translation>
    </message>
    <message>
        <source>feed hold</source>
        <translation>paragem do avanço</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>parado</translation>
    </message>
    <message>
        <source>waiting for the machine</source>
        <translation>à espera da máquina</translation>
    </message>
    <message>
        <source>finished</source>
        <translation>terminado</translation>
    </message>
    <message>
        <source>error</source>
        <translation>erro</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>interrompido</translation>
    </message>
    <message>
        <source>motion refused the block: {1}</source>
        <translation>o movimento recusou o bloco: {1}</translation>
    </message>
    <message>
        <source>motion stopped: {1}</source>
        <translation>o movimento parou: {1}</translation>
    </message>
    <message>
        <source>column {1} must be greater than 0, not {2}</source>
        <translation>a coluna {1} tem de ser maior que 0, não {2}</translation>
    </message>
    <message>
        <source>column {1} must not be negative, not {2}</source>
        <translation>a coluna {1} não pode ser negativa, não {2}</translation>
    </message>
    <message>
        <source>column {1} needs {2} or {3}, not &quot;{4}&quot;</source>
        <translation>a coluna {1} precisa de {2} ou {3}, não &quot;{4}&quot;</translation>
    </message>
    <message>
        <source>{1} needs the coordinates of its end point</source>
        <translation>{1} precisa das coordenadas do seu ponto final</translation>
    </message>
    <message>
        <source>{1} is a straight probing move in workpiece coordinates: not with G06, G08, G09, G36-G39 or G53</source>
        <translation>{1} é um movimento de apalpação reto em coordenadas da peça: não com G06, G08, G09, G36-G39 ou G53</translation>
    </message>
    <message>
        <source>G75 reached its end point without the probe touching</source>
        <translation>G75 chegou ao ponto final sem que o apalpador tocasse</translation>
    </message>
    <message>
        <source>G76 reached its end point with the probe still touching</source>
        <translation>G76 chegou ao ponto final com o apalpador ainda em contacto</translation>
    </message>
    <message>
        <source>Simulation: a box-shaped workpiece the touch probe touches (G75, probing cycles); the bounds below, machine coordinates of the tool tip</source>
        <translation>Simulação: uma peça em forma de paralelepípedo em que o apalpador toca (G75, ciclos de apalpação); os limites abaixo, em coordenadas de máquina da extremidade da ferramenta</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine X of the tool tip inside it</source>
        <translation>Peça simulada para apalpação: X de máquina mínimo da extremidade da ferramenta dentro dela</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine X of the tool tip inside it</source>
        <translation>Peça simulada para apalpação: X de máquina máximo da extremidade da ferramenta dentro dela</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine Y of the tool tip inside it</source>
        <translation>Peça simulada para apalpação: Y de máquina mínimo da extremidade da ferramenta dentro dela</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine Y of the tool tip inside it</source>
        <translation>Peça simulada para apalpação: Y de máquina máximo da extremidade da ferramenta dentro dela</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: lowest machine Z of the tool tip inside it</source>
        <translation>Peça simulada para apalpação: Z de máquina mínimo da extremidade da ferramenta dentro dela</translation>
    </message>
    <message>
        <source>Simulated probe workpiece: highest machine Z of the tool tip inside it</source>
        <translation>Peça simulada para apalpação: Z de máquina máximo da extremidade da ferramenta dentro dela</translation>
    </message>
    <message>
        <source>Machine coordinate of the workpiece origin (the default preset); kerf run --work-offset overrides it</source>
        <translation>Coordenada de máquina da origem da peça (o ponto de referência por defeito); kerf run --work-offset sobrepõe-se a ela</translation>
    </message>
    <message>
        <source>{1} needs a programmed feed F greater than 0</source>
        <translation>{1} precisa de um avanço F programado maior que 0</translation>
    </message>
    <message>
        <source>Drilling/
thread</source>
        <translation>Furar/
roscar</translation>
    </message>
    <message>
        <source>Pockets/
studs/slots</source>
        <translation>Caixas/
ilhas/ranhuras</translation>
    </message>
    <message>
        <source>Patterns</source>
        <translation>Padrões</translation>
    </message>
    <message>
        <source>SL cycles</source>
        <translation>Ciclos SL</translation>
    </message>
    <message>
        <source>Coordinate
transform.</source>
        <translation>Conversão de
coordenadas</translation>
    </message>
    <message>
        <source>Special
cycles</source>
        <translation>Ciclos
especiais</translation>
    </message>
    <message>
        <source>SET-UP CLEARANCE</source>
        <translation>DISTÂNCIA SEGURANÇA</translation>
    </message>
    <message>
        <source>DEPTH</source>
        <translation>PROFUNDIDADE</translation>
    </message>
    <message>
        <source>PLUNGING DEPTH</source>
        <translation>PROFUNDIDADE DE PASSO</translation>
    </message>
    <message>
        <source>SURFACE COORDINATE</source>
        <translation>COORD. SUPERFÍCIE</translation>
    </message>
    <message>
        <source>2ND SET-UP CLEARANCE</source>
        <translation>2.ª DIST. SEGURANÇA</translation>
    </message>
    <message>
        <source>MIN. PLUNGING DEPTH</source>
        <translation>PROF. PASSO MÍNIMA</translation>
    </message>
    <message>
        <source>FEED RATE FOR PLNGNG</source>
        <translation>AVANÇO INCREMENTO</translation>
    </message>
    <message>
        <source>FEED RATE FOR MILLING</source>
        <translation>AVANÇO FRESAGEM</translation>
    </message>
    <message>
        <source>RETRACTION FEED RATE</source>
        <translation>AVANÇO RETROCESSO</translation>
    </message>
    <message>
        <source>DWELL TIME AT TOP</source>
        <translation>TEMPO ESPERA EM CIMA</translation>
    </message>
    <message>
        <source>DWELL TIME AT DEPTH</source>
        <translation>TEMPO ESPERA EM BAIXO</translation>
    </message>
    <message>
        <source>DECREMENT</source>
        <translation>VALOR DE REDUÇÃO</translation>
    </message>
    <message>
        <source>NR OF BREAKS</source>
        <translation>ROTURAS DE APARA</translation>
    </message>
    <message>
        <source>DISENGAGING DIRECTN</source>
        <translation>DIREÇÃO AFASTAMENTO</translation>
    </message>
    <message>
        <source>CENTER IN 1ST AXIS</source>
        <translation>CENTRO 1.º EIXO</translation>
    </message>
    <message>
        <source>CENTER IN 2ND AXIS</source>
        <translation>CENTRO 2.º EIXO</translation>
    </message>
    <message>
        <source>FIRST SIDE LENGTH</source>
        <translation>COMPRIMENTO 1.º LADO</translation>
    </message>
    <message>
        <source>2ND SIDE LENGTH</source>
        <translation>COMPRIMENTO 2.º LADO</translation>
    </message>
    <message>
        <source>ANGLE OF ROTATION</source>
        <translation>ÂNGULO DE ROTAÇÃO</translation>
    </message>
    <message>
        <source>STARTNG PNT 1ST AXIS</source>
        <translation>PONTO INICIAL 1.º EIXO</translation>
    </message>
    <message>
        <source>STARTNG PNT 2ND AXIS</source>
        <translation>PONTO INICIAL 2.º EIXO</translation>
    </message>
    <message>
        <source>STARTNG PNT 3RD AXIS</source>
        <translation>PONTO INICIAL 3.º EIXO</translation>
    </message>
    <message>
        <source>SPACING IN 1ST AXIS</source>
        <translation>DISTÂNCIA 1.º EIXO</translation>
    </message>
    <message>
        <source>SPACING IN 2ND AXIS</source>
        <translation>DISTÂNCIA 2.º EIXO</translation>
    </message>
    <message>
        <source>THREAD PITCH</source>
        <translation>PASSO DE ROSCA</translation>
    </message>
    <message>
        <source>NR OF REPETITIONS</source>
        <translation>N.º DE REPETIÇÕES</translation>
    </message>
    <message>
        <source>NUMBER OF COLUMNS</source>
        <translation>NÚMERO DE COLUNAS</translation>
    </message>
    <message>
        <source>NUMBER OF LINES</source>
        <translation>NÚMERO DE LINHAS</translation>
    </message>
    <message>
        <source>PITCH CIRCLE DIAMETR</source>
        <translation>DIÂM. CÍRC. TEÓRICO</translation>
    </message>
    <message>
        <source>STARTING ANGLE</source>
        <translation>ÂNGULO INICIAL</translation>
    </message>
    <message>
        <source>STOPPING ANGLE</source>
        <translation>ÂNGULO FINAL</translation>
    </message>
    <message>
        <source>STEPPING ANGLE</source>
        <translation>INCREMENTO ANGULAR</translation>
    </message>
    <message>
        <source>DEPTH OF COUNTERBORE</source>
        <translation>PROF. REBAIXAMENTO</translation>
    </message>
    <message>
        <source>MATERIAL THICKNESS</source>
        <translation>ESPESSURA MATERIAL</translation>
    </message>
    <message>
        <source>OFF-CENTER DISTANCE</source>
        <translation>DIST. EXCÊNTRICA</translation>
    </message>
    <message>
        <source>TOOL EDGE HEIGHT</source>
        <translation>ALTURA DA ARESTA</translation>
    </message>
    <message>
        <source>F PRE-POSITIONING</source>
        <translation>AVANÇO POSIC. PRÉVIO</translation>
    </message>
    <message>
        <source>F COUNTERSINKING</source>
        <translation>AVANÇO REBAIXAMENTO</translation>
    </message>
    <message>
        <source>DIST FOR CHIP BRKNG</source>
        <translation>RETROCESSO ROT. APARA</translation>
    </message>
    <message>
        <source>DEPTH FOR CHIP BRKNG</source>
        <translation>PROF. ROTURA APARA</translation>
    </message>
    <message>
        <source>UPPER ADV STOP DIST</source>
        <translation>PARAGEM PRÉVIA SUP.</translation>
    </message>
    <message>
        <source>LOWER ADV STOP DIST</source>
        <translation>PARAGEM PRÉVIA INF.</translation>
    </message>
    <message>
        <source>MOVE TO CLEARANCE</source>
        <translation>DESLOC. ALT. SEGURA</translation>
    </message>
    <message>
        <source>NOMINAL DIAMETER</source>
        <translation>DIÂMETRO NOMINAL</translation>
    </message>
    <message>
        <source>ANGLE OF SPINDLE</source>
        <translation>ÂNGULO DO MANDRIL</translation>
    </message>
    <message>
        <source>DATUM NUMBER</source>
        <translation>NÚMERO PONTO ZERO</translation>
    </message>
    <message>
        <source>ROUGHING DIAMETER</source>
        <translation>DIÂMETRO DESBASTE</translation>
    </message>
    <message>
        <source>SELECT DIA./DEPTH</source>
        <translation>SELEÇÃO DIÂM./PROF.</translation>
    </message>
    <message>
        <source>DIAMETER</source>
        <translation>DIÂMETRO</translation>
    </message>
    <message>
        <source>SELECT POS. HEIGHT</source>
        <translation>SELEÇÃO ALTURA POS.</translation>
    </message>
    <message>
        <source>CLIMB OR UP-CUT</source>
        <translation>SINCRON./CONTRAMARCHA</translation>
    </message>
    <message>
        <source>THREADS PER STEP</source>
        <translation>PASSOS POR VOLTA</translation>
    </message>
    <message>
        <source>COUNTERSINKING DEPTH</source>
        <translation>PROF. REBAIXAMENTO</translation>
    </message>
    <message>
        <source>CLEARANCE TO SIDE</source>
        <translation>DISTÂNCIA LATERAL</translation>
    </message>
    <message>
        <source>DEPTH AT FRONT</source>
        <translation>PROFUNDIDADE FRONTAL</translation>
    </message>
    <message>
        <source>OFFSET AT FRONT</source>
        <translation>DESVIO FRONTAL</translation>
    </message>
    <message>
        <source>COUNTERSINK PROCESS</source>
        <translation>PROCESSO REBAIXAMENTO</translation>
    </message>
    <message>
        <source>TYPE OF TRAVERSE</source>
        <translation>TIPO DE DESLOCAÇÃO</translation>
    </message>
    <message>
        <source>TEXT POSITION</source>
        <translation>POSIÇÃO DO TEXTO</translation>
    </message>
    <message>
        <source>ALLOWANCE FOR FLOOR</source>
        <translation>SOBRE-MEDIDA FUNDO</translation>
    </message>
    <message>
        <source>MAX. OVERLAP</source>
        <translation>SOBREPOSIÇÃO MÁX.</translation>
    </message>
    <message>
        <source>STARTING POINT</source>
        <translation>PONTO INICIAL</translation>
    </message>
    <message>
        <source>FINISHING FEED RATE</source>
        <translation>AVANÇO ACABAMENTO</translation>
    </message>
    <message>
        <source>END POINT 3RD AXIS</source>
        <translation>PONTO FINAL 3.º EIXO</translation>
    </message>
    <message>
        <source>STRATEGY</source>
        <translation>ESTRATÉGIA</translation>
    </message>
    <message>
        <source>DEPTH REFERENCE</source>
        <translation>REFERÊNCIA PROF.</translation>
    </message>
    <message>
        <source>FEED RATE FACTOR</source>
        <translation>FATOR DE AVANÇO</translation>
    </message>
    <message>
        <source>RPM FACTOR</source>
        <translation>FATOR DE VELOCIDADE</translation>
    </message>
    <message>
        <source>DIR. OF SPINDLE ROT.</source>
        <translation>SENTIDO ROT. MANDRIL</translation>
    </message>
    <message>
        <source>ROT.SPEED INFEED/OUT</source>
        <translation>VEL. ENTRADA/SAÍDA</translation>
    </message>
    <message>
        <source>ROT. SPEED DRILLING</source>
        <translation>VELOCIDADE FURAR</translation>
    </message>
    <message>
        <source>COOLANT ON</source>
        <translation>REFRIGERANTE LIGADO</translation>
    </message>
    <message>
        <source>COOLANT OFF</source>
        <translation>REFRIGERANTE DESLIG.</translation>
    </message>
    <message>
        <source>DWELL DEPTH</source>
        <translation>PROFUNDIDADE ESPERA</translation>
    </message>
    <message>
        <source>ENGRAVING TEXT</source>
        <translation>TEXTO A GRAVAR</translation>
    </message>
    <message>
        <source>FEED FOR APPROACH</source>
        <translation>AVANÇO APROXIMAÇÃO</translation>
    </message>
    <message>
        <source>CHARACTER HEIGHT</source>
        <translation>ALTURA CARACTERES</translation>
    </message>
    <message>
        <source>SPACE FACTOR</source>
        <translation>FATOR DE DISTÂNCIA</translation>
    </message>
    <message>
        <source>FONT</source>
        <translation>FONTE</translation>
    </message>
    <message>
        <source>TEXT LAYOUT</source>
        <translation>DISPOSIÇÃO DO TEXTO</translation>
    </message>
    <message>
        <source>CIRCLE RADIUS</source>
        <translation>RAIO DO CÍRCULO</translation>
    </message>
    <message>
        <source>MAX. TEXT LENGTH</source>
        <translation>COMPR. MÁX. TEXTO</translation>
    </message>
    <message>
        <source>F COUNTERBORING</source>
        <translation>AVANÇO REBAIX. INV.</translation>
    </message>
    <message>
        <source>DEPTH OF THREAD</source>
        <translation>PROFUNDIDADE ROSCA</translation>
    </message>
    <message>
        <source>MAX. PLUNGING DEPTH</source>
        <translation>PROF. PASSO MÁXIMA</translation>
    </message>
    <message>
        <source>TOTAL HOLE DEPTH</source>
        <translation>PROF. TOTAL FURO</translation>
    </message>
    <message>
        <source>%1: %2 needs a positive feed after it, e.g. %2 0.1</source>
        <translation>%1: %2 precisa de um avanço positivo a seguir, p. ex. %2 0.1</translation>
    </message>
    <message>
        <source>%1: %2 is not allowed here; enter a number</source>
        <translation>%1: %2 não é permitido aqui; introduza um número</translation>
    </message>
    <message>
        <source>%1: %2 is not allowed here; allowed: a number, %3</source>
        <translation>%1: %2 não é permitido aqui; permitido: um número, %3</translation>
    </message>
    <message>
        <source>%1: enter a value</source>
        <translation>%1: introduza um valor</translation>
    </message>
    <message>
        <source>%1: the text must not contain &quot;</source>
        <translation>%1: o texto não pode conter &quot;</translation>
    </message>
    <message>
        <source>%1: enter axis letters separated by blanks, e.g. X Y</source>
        <translation>%1: introduza letras de eixo separadas por espaços, p. ex. X Y</translation>
    </message>
    <message>
        <source>%1: #n needs a datum number, e.g. #5</source>
        <translation>%1: #n precisa de um número de ponto zero, p. ex. #5</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: &quot;%2&quot; não é um número</translation>
    </message>
    <message>
        <source>%1: enter a whole number from %2 to %3</source>
        <translation>%1: introduza um número inteiro de %2 a %3</translation>
    </message>
    <message>
        <source>%1: %2 is outside the range %3 to %4</source>
        <translation>%1: %2 está fora da gama %3 a %4</translation>
    </message>
    <message>
        <source>%1 coordinate of the end point (I before the value: incremental)</source>
        <translation>Coordenada %1 do ponto final (I antes do valor: incremental)</translation>
    </message>
    <message>
        <source>Circle radius (negative: arc greater than 180°)</source>
        <translation>Raio do círculo (negativo: arco maior que 180°)</translation>
    </message>
    <message>
        <source>Chamfer length</source>
        <translation>Comprimento do chanfre</translation>
    </message>
    <message>
        <source>Rounding radius</source>
        <translation>Raio de arredondamento</translation>
    </message>
    <message>
        <source>Direction of rotation (DR-: clockwise, DR+: counterclockwise)</source>
        <translation>Sentido de rotação (DR-: horário, DR+: anti-horário)</translation>
    </message>
    <message>
        <source>Radius compensation (RL left, RR right of the contour, R0 none)</source>
        <translation>Correção de raio (RL à esquerda, RR à direita do contorno, R0 nenhuma)</translation>
    </message>
    <message>
        <source>Feed rate (FMAX: rapid traverse, FAUTO: from TOOL CALL)</source>
        <translation>Avanço (FMAX: marcha rápida, FAUTO: do TOOL CALL)</translation>
    </message>
    <message>
        <source>Miscellaneous functions, e.g. 3 8</source>
        <translation>Funções auxiliares, p. ex. 3 8</translation>
    </message>
    <message>
        <source>Tool number or name</source>
        <translation>Número ou nome da ferramenta</translation>
    </message>
    <message>
        <source>Spindle axis</source>
        <translation>Eixo do mandril</translation>
    </message>
    <message>
        <source>Spindle speed S [1/min]</source>
        <translation>Velocidade do mandril S [1/min]</translation>
    </message>
    <message>
        <source>Delta length DL</source>
        <translation>Comprimento delta DL</translation>
    </message>
    <message>
        <source>Delta radius DR</source>
        <translation>Raio delta DR</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a coordinate</source>
        <translation>%1: &quot;%2&quot; não é uma coordenada</translation>
    </message>
    <message>
        <source>%1: enter a radius other than 0</source>
        <translation>%1: introduza um raio diferente de 0</translation>
    </message>
    <message>
        <source>%1: enter a positive number</source>
        <translation>%1: introduza um número positivo</translation>
    </message>
    <message>
        <source>%1: enter a feed rate, FMAX or FAUTO</source>
        <translation>%1: introduza um avanço, FMAX ou FAUTO</translation>
    </message>
    <message>
        <source>%1: enter M function numbers, e.g. 3 8</source>
        <translation>%1: introduza números de funções M, p. ex. 3 8</translation>
    </message>
    <message>
        <source>%1: enter a tool number or a name</source>
        <translation>%1: introduza um número ou um nome de ferramenta</translation>
    </message>
    <message>
        <source>%1: choose one of %2</source>
        <translation>%1: escolha um de %2</translation>
    </message>
    <message>
        <source>%1: enter at least one coordinate</source>
        <translation>%1: introduza pelo menos uma coordenada</translation>
    </message>
    <message>
        <source>Cycle
overview</source>
        <translation>Resumo
de ciclos</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Voltar</translation>
    </message>
    <message>
        <source>Edit
cycle</source>
        <translation>Editar
ciclo</translation>
    </message>
    <message>
        <source>Put the cursor on a CYCL DEF block to edit it.</source>
        <translation>Coloque o cursor num bloco CYCL DEF para o editar.</translation>
    </message>
    <message>
        <source>the file is outside the NC root</source>
        <translation>o ficheiro está fora da raiz NC</translation>
    </message>
    <message>
        <source>the file does not exist</source>
        <translation>o ficheiro não existe</translation>
    </message>
    <message>
        <source>the NC root itself cannot be changed</source>
        <translation>a própria raiz NC não pode ser alterada</translation>
    </message>
    <message>
        <source>the file is protected</source>
        <translation>o ficheiro está protegido</translation>
    </message>
    <message>
        <source>a file with this name exists already</source>
        <translation>já existe um ficheiro com este nome</translation>
    </message>
    <message>
        <source>cannot copy: {1}</source>
        <translation>não é possível copiar: {1}</translation>
    </message>
    <message>
        <source>cannot move: {1}</source>
        <translation>não é possível mover: {1}</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a valid file name</source>
        <translation>&apos;{1}&apos; não é um nome de ficheiro válido</translation>
    </message>
    <message>
        <source>cannot delete: {1}</source>
        <translation>não é possível apagar: {1}</translation>
    </message>
    <message>
        <source>cannot create the folder: {1}</source>
        <translation>não é possível criar a pasta: {1}</translation>
    </message>
    <message>
        <source>cannot change the protection: {1}</source>
        <translation>não é possível alterar a proteção: {1}</translation>
    </message>
    <message>
        <source>{1} needs a number, not &quot;{2}&quot;</source>
        <translation>{1} precisa de um número, não &quot;{2}&quot;</translation>
    </message>
    <message>
        <source>{1} must be from {2} to {3}</source>
        <translation>{1} tem de estar entre {2} e {3}</translation>
    </message>
    <message>
        <source>this table has a fixed row for every entry: edit the values instead</source>
        <translation>esta tabela tem uma linha fixa por entrada: edite os valores</translation>
    </message>
    <message>
        <source>the table is full ({1}{2} to {1}{3})</source>
        <translation>a tabela está cheia ({1}{2} a {1}{3})</translation>
    </message>
    <message>
        <source>the test run stopped after {1} blocks: endless loop?</source>
        <translation>o teste do programa parou após {1} blocos: ciclo infinito?</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not a regular file</source>
        <translation>&apos;{1}&apos; não é um ficheiro regular</translation>
    </message>
    <message>
        <source>cannot write program {1}: {2}</source>
        <translation>não é possível escrever o programa {1}: {2}</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is a link: Kerf does not write through links</source>
        <translation>&apos;{1}&apos; é uma ligação: o Kerf não escreve através de ligações</translation>
    </message>
    <message>
        <source>and {1} more diagnostics</source>
        <translation>e mais {1} diagnósticos</translation>
    </message>
    <message>
        <source>overflow: the result of &apos;{1}&apos; is too large</source>
        <translation>estouro: o resultado de &apos;{1}&apos; é grande demais</translation>
    </message>
    <message>
        <source>an expression may nest at most {1} levels</source>
        <translation>uma expressão pode aninhar no máximo {1} níveis</translation>
    </message>
    <message>
        <source>P{1}: the value is too large (overflow)</source>
        <translation>P{1}: o valor é grande demais (estouro)</translation>
    </message>
    <message>
        <source>{1}{2} holds no finite number</source>
        <translation>{1}{2} não contém um número finito</translation>
    </message>
    <message>
        <source>a formula may nest at most {1} levels</source>
        <translation>uma fórmula pode aninhar no máximo {1} níveis</translation>
    </message>
    <message>
        <source>a string may hold at most {1} characters, not {2}</source>
        <translation>uma cadeia pode ter no máximo {1} caracteres, não {2}</translation>
    </message>
    <message>
        <source>{1} = {2} is outside the range of the control (at most {3})</source>
        <translation>{1} = {2} está fora da faixa do comando (no máximo {3})</translation>
    </message>
    <message>
        <source>Programs and MDI run only after the axes are homed (Home all); false lets a machine without reference switches run from power-on</source>
        <translation>Programas e MDI só funcionam após referenciar os eixos (Referenciar todos); false deixa uma máquina sem chaves de referência funcionar desde a ligação</translation>
    </message>
    <message>
        <source>Order of the axis in Home all: lower numbers are homed first</source>
        <translation>Ordem do eixo em Referenciar todos: números menores são referenciados primeiro</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; changed while it was opened: a link appeared</source>
        <translation>&apos;{1}&apos; mudou enquanto era aberto: apareceu uma ligação</translation>
    </message>
    <message>
        <source>{1} must be 0, 1 or 2 for tapping</source>
        <translation>{1} deve ser 0, 1 ou 2 para roscar com macho</translation>
    </message>
    <message>
        <source>rigid tapping needs a feed and a spindle speed</source>
        <translation>o roscamento rígido precisa de um avanço e de uma velocidade do eixo-árvore</translation>
    </message>
    <message>
        <source>the pecks shrink below 0.001 mm before the depth I: program L</source>
        <translation>os aprofundamentos ficam abaixo de 0,001 mm antes da profundidade I: programe L</translation>
    </message>
    <message>
        <source>the groove has no depth</source>
        <translation>a ranhura não tem profundidade</translation>
    </message>
    <message>
        <source>the groove is narrower than the tool&apos;s cutting width NOSEW</source>
        <translation>a ranhura é mais estreita que a largura de corte NOSEW da ferramenta</translation>
    </message>
    <message>
        <source>C is not programmed and the tool has no cutting width NOSEW</source>
        <translation>C não está programado e a ferramenta não tem largura de corte NOSEW</translation>
    </message>
    <message>
        <source>the tool position is not correct for the cycle ({1})</source>
        <translation>a posição da ferramenta não é correta para o ciclo ({1})</translation>
    </message>
    <message>
        <source>the cycle would need more than {1} moves: {2} is too small</source>
        <translation>o ciclo precisaria de mais de {1} movimentos: {2} é pequeno demais</translation>
    </message>
    <message>
        <source>the section has no length along the passes</source>
        <translation>o trecho não tem comprimento na direção das passadas</translation>
    </message>
    <message>
        <source>the thread has no length along its axis</source>
        <translation>a rosca não tem comprimento ao longo do seu eixo</translation>
    </message>
    <message>
        <source>{1} leaves no thread to cut between the start and the end</source>
        <translation>{1} não deixa rosca para cortar entre o início e o fim</translation>
    </message>
    <message>
        <source>{1} is not a parameter of {2}</source>
        <translation>{1} não é um parâmetro de {2}</translation>
    </message>
    <message>
        <source>{1} of {2} needs a value</source>
        <translation>{1} de {2} precisa de um valor</translation>
    </message>
    <message>
        <source>{1} of {2} cannot be 0</source>
        <translation>{1} de {2} não pode ser 0</translation>
    </message>
    <message>
        <source>{1} needs its parameter {2}</source>
        <translation>{1} precisa do seu parâmetro {2}</translation>
    </message>
    <message>
        <source>{1}: M (pitch change) cannot be programmed with K (repass)</source>
        <translation>{1}: M (variação de passo) não pode ser programado com K (repasse)</translation>
    </message>
    <message>
        <source>{1} and {2}: one canned cycle per block</source>
        <translation>{1} e {2}: um ciclo fixo por bloco</translation>
    </message>
    <message>
        <source>the start and the end of an arc are not on one circle about its centre</source>
        <translation>o início e o fim de um arco não estão num círculo em torno do seu centro</translation>
    </message>
    <message>
        <source>an arc of the profile must stay within a quarter circle</source>
        <translation>um arco do perfil deve ficar dentro de um quarto de círculo</translation>
    </message>
    <message>
        <source>label N{1} of the profile is not in the program</source>
        <translation>o rótulo N{1} do perfil não está no programa</translation>
    </message>
    <message>
        <source>the profile ends (E) before it starts (S)</source>
        <translation>o perfil termina (E) antes de começar (S)</translation>
    </message>
    <message>
        <source>a profile holds no high-level blocks</source>
        <translation>um perfil não contém blocos de alto nível</translation>
    </message>
    <message>
        <source>{1} is not allowed in a profile</source>
        <translation>{1} não é permitido num perfil</translation>
    </message>
    <message>
        <source>the profile has more than 10000 elements</source>
        <translation>o perfil tem mais de 10000 elementos</translation>
    </message>
    <message>
        <source>this machine has no axis {1}</source>
        <translation>esta máquina não tem eixo {1}</translation>
    </message>
    <message>
        <source>MACHINING OPERATION</source>
        <translation>TIPO DE MAQUINAGEM</translation>
    </message>
    <message>
        <source>CORNER RADIUS</source>
        <translation>RAIO DE ESQUINA</translation>
    </message>
    <message>
        <source>WORKPIECE BLANK DIA.</source>
        <translation>DIÂMETRO DO BLOCO</translation>
    </message>
    <message>
        <source>CIRCLE DIAMETER</source>
        <translation>DIÂMETRO DO CÍRCULO</translation>
    </message>
    <message>
        <source>ANGULAR LENGTH</source>
        <translation>COMPRIMENTO ANGULAR</translation>
    </message>
    <message>
        <source>INFEED FOR FINISHING</source>
        <translation>PASSO DE ACABAMENTO</translation>
    </message>
    <message>
        <source>PLUNGE</source>
        <translation>AFUNDAMENTO</translation>
    </message>
    <message>
        <source>ALLOWANCE FOR SIDE</source>
        <translation>SOBREMEDIDA LATERAL</translation>
    </message>
    <message>
        <source>WORKPC. BLANK SIDE 1</source>
        <translation>BLOCO LADO 1</translation>
    </message>
    <message>
        <source>WORKPC. BLANK SIDE 2</source>
        <translation>BLOCO LADO 2</translation>
    </message>
    <message>
        <source>APPROACH POSITION</source>
        <translation>POSIÇÃO APROXIMAÇÃO</translation>
    </message>
    <message>
        <source>FEED RATE REFERENCE</source>
        <translation>REFERÊNCIA AVANÇO</translation>
    </message>
    <message>
        <source>REF-CIRCLE DIAMETER</source>
        <translation>DIÂM. CÍRC. REFERÊNCIA</translation>
    </message>
    <message>
        <source>NUMBER OF CORNERS</source>
        <translation>NÚMERO DE ESQUINAS</translation>
    </message>
    <message>
        <source>REFERENCE CIRCLE</source>
        <translation>CÍRCULO REFERÊNCIA</translation>
    </message>
    <message>
        <source>POCKET POSITION</source>
        <translation>POSIÇÃO CAIXA</translation>
    </message>
    <message>
        <source>SLOT LENGTH</source>
        <translation>COMPRIMENTO RANHURA</translation>
    </message>
    <message>
        <source>SLOT WIDTH</source>
        <translation>LARGURA RANHURA</translation>
    </message>
    <message>
        <source>SLOT POSITION</source>
        <translation>POSIÇÃO RANHURA</translation>
    </message>
    <message>
        <source>REF. SLOT POSITION</source>
        <translation>REF. POSIÇÃO RANHURA</translation>
    </message>
    <message>
        <source>RADIUS / CHAMFER</source>
        <translation>RAIO / CHANFRE</translation>
    </message>
    <message>
        <source>STUD POSITION</source>
        <translation>POSIÇÃO ILHA</translation>
    </message>
    <message>
        <source>FINISHED PART DIA.</source>
        <translation>DIÂMETRO PEÇA ACABADA</translation>
    </message>
    <message>
        <source>Corner radius (0: tool radius)</source>
        <translation>Raio de esquina (0: raio da ferramenta)</translation>
    </message>
    <message>
        <source>RECTANGULAR POCKET</source>
        <translation>CAIXA RETANGULAR</translation>
    </message>
    <message>
        <source>Circle diameter</source>
        <translation>Diâmetro do círculo</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 helical)</source>
        <translation>Estratégia de afundamento (0 vertical, 1 helicoidal)</translation>
    </message>
    <message>
        <source>cycle {1}: vertical plunging (Q366 = 0) needs a tool whose ANGLE is 0 or 90</source>
        <translation>ciclo {1}: o afundamento vertical (Q366 = 0) precisa de uma ferramenta com ANGLE 0 ou 90</translation>
    </message>
    <message>
        <source>CIRCULAR POCKET</source>
        <translation>CAIXA CIRCULAR</translation>
    </message>
    <message>
        <source>Slot length</source>
        <translation>Comprimento da ranhura</translation>
    </message>
    <message>
        <source>Slot width</source>
        <translation>Largura da ranhura</translation>
    </message>
    <message>
        <source>Slot position (0 centre, 1 left end, 2 centre of the left arc, 3 centre of the right arc, 4 right end)</source>
        <translation>Posição da ranhura (0 centro, 1 extremidade esquerda, 2 centro do arco esquerdo, 3 centro do arco direito, 4 extremidade direita)</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width Q219 is larger than its length Q218</source>
        <translation>ciclo {1}: a largura da ranhura Q219 é maior que o seu comprimento Q218</translation>
    </message>
    <message>
        <source>SLOT MILLING</source>
        <translation>FRESAGEM DE RANHURAS</translation>
    </message>
    <message>
        <source>Reference of the slot position (0 centre Q216/Q217, 1 start arc, 2 middle, 3 end arc at the tool position)</source>
        <translation>Referência da posição da ranhura (0 centro Q216/Q217, 1 arco inicial, 2 meio, 3 arco final na posição da ferramenta)</translation>
    </message>
    <message>
        <source>Angular length of the slot</source>
        <translation>Comprimento angular da ranhura</translation>
    </message>
    <message>
        <source>Stepping angle between repetitions</source>
        <translation>Passo angular entre repetições</translation>
    </message>
    <message>
        <source>Number of repetitions</source>
        <translation>Número de repetições</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width Q219 must be smaller than the pitch circle diameter Q375</source>
        <translation>ciclo {1}: a largura da ranhura Q219 tem de ser menor que o diâmetro do círculo primitivo Q375</translation>
    </message>
    <message>
        <source>cycle {1}: the angular length Q248 closes the slot on itself</source>
        <translation>ciclo {1}: o comprimento angular Q248 fecha a ranhura sobre si mesma</translation>
    </message>
    <message>
        <source>CIRCULAR SLOT</source>
        <translation>RANHURA CIRCULAR</translation>
    </message>
    <message>
        <source>Workpiece blank side length 1</source>
        <translation>Comprimento lateral 1 do bloco</translation>
    </message>
    <message>
        <source>Workpiece blank side length 2</source>
        <translation>Comprimento lateral 2 do bloco</translation>
    </message>
    <message>
        <source>Corner radius (+) or chamfer (-)</source>
        <translation>Raio de esquina (+) ou chanfre (-)</translation>
    </message>
    <message>
        <source>Approach position (0 right of the stud, 1-4 corners)</source>
        <translation>Posição de aproximação (0 à direita da ilha, 1-4 esquinas)</translation>
    </message>
    <message>
        <source>cycle {1}: the workpiece blank is smaller than the finished part</source>
        <translation>ciclo {1}: o bloco é menor do que a peça acabada</translation>
    </message>
    <message>
        <source>RECTANGULAR STUD</source>
        <translation>ILHA RETANGULAR</translation>
    </message>
    <message>
        <source>Finished part diameter</source>
        <translation>Diâmetro da peça acabada</translation>
    </message>
    <message>
        <source>Workpiece blank diameter</source>
        <translation>Diâmetro do bloco</translation>
    </message>
    <message>
        <source>CIRCULAR STUD</source>
        <translation>ILHA CIRCULAR</translation>
    </message>
    <message>
        <source>Reference circle (0 inscribed, 1 circumscribed)</source>
        <translation>Círculo de referência (0 inscrito, 1 circunscrito)</translation>
    </message>
    <message>
        <source>Reference circle diameter</source>
        <translation>Diâmetro do círculo de referência</translation>
    </message>
    <message>
        <source>Number of corners</source>
        <translation>Número de esquinas</translation>
    </message>
    <message>
        <source>Angle of the first corner</source>
        <translation>Ângulo da primeira esquina</translation>
    </message>
    <message>
        <source>cycle {1}: a polygon needs at least 3 corners (Q572)</source>
        <translation>ciclo {1}: um polígono precisa de pelo menos 3 esquinas (Q572)</translation>
    </message>
    <message>
        <source>cycle {1}: the corner radius or chamfer Q220 is too large for the sides of the polygon</source>
        <translation>ciclo {1}: o raio de esquina ou o chanfre Q220 é demasiado grande para os lados do polígono</translation>
    </message>
    <message>
        <source>POLYGON STUD</source>
        <translation>ILHA POLIGONAL</translation>
    </message>
    <message>
        <source>cycle {1} needs a tool with a radius greater than 0</source>
        <translation>o ciclo {1} precisa de uma ferramenta com raio maior que 0</translation>
    </message>
    <message>
        <source>cycle {1}: helical or reciprocating plunging (Q366) needs the plunge angle ANGLE of the tool</source>
        <translation>ciclo {1}: o afundamento helicoidal ou pendular (Q366) precisa do ângulo de afundamento ANGLE da ferramenta</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is too large for the programmed size and finishing allowance</source>
        <translation>ciclo {1}: a ferramenta é demasiado grande para a medida programada e a sobremedida de acabamento</translation>
    </message>
    <message>
        <source>cycle {1}: no room for the helical plunge: the helix needs a diameter of twice the tool diameter</source>
        <translation>ciclo {1}: não há espaço para o afundamento helicoidal: a hélice precisa do dobro do diâmetro da ferramenta</translation>
    </message>
    <message>
        <source>cycle {1}: no room for reciprocating plunging: it needs a length of twice the tool diameter</source>
        <translation>ciclo {1}: não há espaço para o afundamento pendular: precisa de um comprimento do dobro do diâmetro da ferramenta</translation>
    </message>
    <message>
        <source>Machining operation (0 roughing and finishing, 1 roughing, 2 finishing)</source>
        <translation>Tipo de maquinagem (0 desbaste e acabamento, 1 desbaste, 2 acabamento)</translation>
    </message>
    <message>
        <source>First side length</source>
        <translation>Comprimento do primeiro lado</translation>
    </message>
    <message>
        <source>Second side length</source>
        <translation>Comprimento do segundo lado</translation>
    </message>
    <message>
        <source>Finishing allowance for the side</source>
        <translation>Sobremedida de acabamento lateral</translation>
    </message>
    <message>
        <source>Position (0 centre, 1 lower left, 2 lower right, 3 upper right, 4 upper left corner)</source>
        <translation>Posição (0 centro, 1 esquina inferior esquerda, 2 inferior direita, 3 superior direita, 4 superior esquerda)</translation>
    </message>
    <message>
        <source>Infeed for finishing (0: one infeed)</source>
        <translation>Passo de acabamento (0: um passo)</translation>
    </message>
    <message>
        <source>Feed rate reference (0 tool centre, 1 cutting edge when side finishing, 2 also floor finishing, 3 always)</source>
        <translation>Referência do avanço (0 centro da ferramenta, 1 gume no acabamento lateral, 2 também no acabamento do fundo, 3 sempre)</translation>
    </message>
    <message>
        <source>Code number asked before machine parameters may be edited</source>
        <translation>Código numérico pedido antes de editar os parâmetros da máquina</translation>
    </message>
    <message>
        <source>the profile has no length</source>
        <translation>o perfil não tem comprimento</translation>
    </message>
    <message>
        <source>the profile cannot be copied at the distance of a pass: it is too narrow</source>
        <translation>o perfil não pode ser copiado à distância de uma passada: é estreito demais</translation>
    </message>
    <message>
        <source>the profile runs back against the passes (an undercut): the tool cannot reach it</source>
        <translation>o perfil volta contra as passadas (um rebaixo): a ferramenta não o alcança</translation>
    </message>
    <message>
        <source>the section runs back under the material</source>
        <translation>o trecho volta por baixo do material</translation>
    </message>
    <message>
        <source>{1} cannot make an arc to this end point</source>
        <translation>{1} não consegue formar um arco até este ponto final</translation>
    </message>
    <message>
        <source>a profile has one raw-stock part (one G00)</source>
        <translation>um perfil tem uma só parte de material bruto (um G00)</translation>
    </message>
    <message>
        <source>the G00 block starts the raw-stock profile: it needs its point</source>
        <translation>o bloco G00 inicia o perfil do material bruto: precisa do seu ponto</translation>
    </message>
    <message>
        <source>cycle parameters belong to a cycle block (G2xx, G4xx ...)</source>
        <translation>os parâmetros de ciclo pertencem a um bloco de ciclo (G2xx, G4xx ...)</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is not allowed in this block</source>
        <translation>&apos;{1}&apos; não é permitido neste bloco</translation>
    </message>
    <message>
        <source>program name expected after &apos;%&apos;</source>
        <translation>esperado nome de programa após &apos;%&apos;</translation>
    </message>
    <message>
        <source>P0{1} expected</source>
        <translation>esperado P0{1}</translation>
    </message>
    <message>
        <source>label number expected</source>
        <translation>esperado número de label</translation>
    </message>
    <message>
        <source>two path functions in one block</source>
        <translation>duas funções de trajetória num bloco</translation>
    </message>
    <message>
        <source>G70/G71 belong to the program header &apos;%NAME&apos;</source>
        <translation>G70/G71 pertencem ao cabeçalho do programa &apos;%NAME&apos;</translation>
    </message>
    <message>
        <source>G{1} and G{2} cannot share a block</source>
        <translation>G{1} e G{2} não podem partilhar um bloco</translation>
    </message>
    <message>
        <source>value expected after &apos;{1}&apos;</source>
        <translation>esperado valor após &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>a label has no repeat count</source>
        <translation>um label não tem número de repetições</translation>
    </message>
    <message>
        <source>label number expected (G98 L1)</source>
        <translation>esperado número de label (G98 L1)</translation>
    </message>
    <message>
        <source>tool number expected (T)</source>
        <translation>esperado número de ferramenta (T)</translation>
    </message>
    <message>
        <source>the plane belongs to G30</source>
        <translation>o plano pertence a G30</translation>
    </message>
    <message>
        <source>R expected after G{1}</source>
        <translation>esperado R após G{1}</translation>
    </message>
    <message>
        <source>unknown G function G{1}</source>
        <translation>função G desconhecida G{1}</translation>
    </message>
    <message>
        <source>G17/G18/G19 belong to a tool call (T) or a blank (G30)</source>
        <translation>G17/G18/G19 pertencem a uma chamada de ferramenta (T) ou a um bloco (G30)</translation>
    </message>
    <message>
        <source>no path function (G00, G01, G02 ...) is active</source>
        <translation>nenhuma função de trajetória (G00, G01, G02 ...) está ativa</translation>
    </message>
    <message>
        <source>a feed rate F is not allowed with rapid G{1}</source>
        <translation>não é permitido um avanço F com o rápido G{1}</translation>
    </message>
    <message>
        <source>{1} expected after G{2}</source>
        <translation>esperado {1} após G{2}</translation>
    </message>
    <message>
        <source>program name expected (P01 &quot;NAME&quot;)</source>
        <translation>esperado nome de programa (P01 &quot;NAME&quot;)</translation>
    </message>
    <message>
        <source>contour labels expected (P01 1)</source>
        <translation>esperados labels de contorno (P01 1)</translation>
    </message>
    <message>
        <source>text after the block end &apos;*&apos;</source>
        <translation>texto após o fim de bloco &apos;*&apos;</translation>
    </message>
    <message>
        <source>closing &apos;&quot;&apos; missing</source>
        <translation>falta o &apos;&quot;&apos; de fecho</translation>
    </message>
    <message>
        <source>number expected after &apos;{1}&apos;</source>
        <translation>esperado número após &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>repeat count expected after &apos;,&apos;</source>
        <translation>esperado número de repetições após &apos;,&apos;</translation>
    </message>
    <message>
        <source>cycle {1}: the stepping angle Q247 must be at least 5 degrees</source>
        <translation>ciclo {1}: o incremento angular Q247 tem de ser de pelo menos 5 graus</translation>
    </message>
    <message>
        <source>cycle {1}: the touch points give no circle</source>
        <translation>ciclo {1}: os pontos de apalpação não formam um círculo</translation>
    </message>
    <message>
        <source>1st touch point, main axis</source>
        <translation>1.º ponto de apalpação, eixo principal</translation>
    </message>
    <message>
        <source>1st touch point, secondary axis</source>
        <translation>1.º ponto de apalpação, eixo secundário</translation>
    </message>
    <message>
        <source>Spacing of touch points 1 and 2 in the main axis</source>
        <translation>Distância entre os pontos de apalpação 1 e 2 no eixo principal</translation>
    </message>
    <message>
        <source>3rd touch point, main axis</source>
        <translation>3.º ponto de apalpação, eixo principal</translation>
    </message>
    <message>
        <source>3rd touch point, secondary axis</source>
        <translation>3.º ponto de apalpação, eixo secundário</translation>
    </message>
    <message>
        <source>Spacing of touch points 3 and 4 in the secondary axis</source>
        <translation>Distância entre os pontos de apalpação 3 e 4 no eixo secundário</translation>
    </message>
    <message>
        <source>Basic rotation too: 0 no, 1 yes</source>
        <translation>Definir também a rotação básica: 0 não, 1 sim</translation>
    </message>
    <message>
        <source>Corner, main axis</source>
        <translation>Esquina, eixo principal</translation>
    </message>
    <message>
        <source>Corner, secondary axis</source>
        <translation>Esquina, eixo secundário</translation>
    </message>
    <message>
        <source>Corner: 1 (-M -S), 2 (+M -S), 3 (+M +S), 4 (-M +S)</source>
        <translation>Esquina: 1 (-M -S), 2 (+M -S), 3 (+M +S), 4 (-M +S)</translation>
    </message>
    <message>
        <source>Bolt-circle centre, main axis</source>
        <translation>Centro do círculo de furos, eixo principal</translation>
    </message>
    <message>
        <source>Bolt-circle centre, secondary axis</source>
        <translation>Centro do círculo de furos, eixo secundário</translation>
    </message>
    <message>
        <source>Nominal bolt-circle diameter</source>
        <translation>Diâmetro nominal do círculo de furos</translation>
    </message>
    <message>
        <source>Polar angle of the 1st hole centre</source>
        <translation>Ângulo polar do centro do 1.º furo</translation>
    </message>
    <message>
        <source>Polar angle of the 2nd hole centre</source>
        <translation>Ângulo polar do centro do 2.º furo</translation>
    </message>
    <message>
        <source>Polar angle of the 3rd hole centre</source>
        <translation>Ângulo polar do centro do 3.º furo</translation>
    </message>
    <message>
        <source>cycle {1}: the two edges are parallel</source>
        <translation>ciclo {1}: as duas arestas são paralelas</translation>
    </message>
    <message>
        <source>cycle {1}: the hole centres give no circle</source>
        <translation>ciclo {1}: os centros dos furos não formam um círculo</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE CORNER</source>
        <translation>PONTO DE REFERÊNCIA ESQUINA EXTERIOR</translation>
    </message>
    <message>
        <source>DATUM INSIDE CORNER</source>
        <translation>PONTO DE REFERÊNCIA ESQUINA INTERIOR</translation>
    </message>
    <message>
        <source>DATUM CIRCLE CENTER</source>
        <translation>PONTO DE REFERÊNCIA CENTRO DO CÍRCULO DE FUROS</translation>
    </message>
    <message>
        <source>Nominal intersection, main axis</source>
        <translation>Ponto de interseção nominal, eixo principal</translation>
    </message>
    <message>
        <source>Nominal intersection, secondary axis</source>
        <translation>Ponto de interseção nominal, eixo secundário</translation>
    </message>
    <message>
        <source>Nominal position in the tool axis: the measuring height</source>
        <translation>Posição nominal no eixo da ferramenta: a altura de medição</translation>
    </message>
    <message>
        <source>Tolerance of the 1st edge along its normal, e.g. &quot;0.1-0.1&quot;</source>
        <translation>Tolerância da 1.ª aresta ao longo da sua normal, p. ex. &quot;0.1-0.1&quot;</translation>
    </message>
    <message>
        <source>Nominal angle of the 1st line</source>
        <translation>Ângulo nominal da 1.ª reta</translation>
    </message>
    <message>
        <source>Probing direction of the 1st line: +1 angle + 90, -1 - 90</source>
        <translation>Direção de apalpação da 1.ª reta: +1 ângulo + 90, -1 - 90</translation>
    </message>
    <message>
        <source>Intersection to the 1st touch point of the 1st line</source>
        <translation>Distância do ponto de interseção ao 1.º ponto de apalpação da 1.ª reta</translation>
    </message>
    <message>
        <source>Intersection to the 2nd touch point of the 1st line</source>
        <translation>Distância do ponto de interseção ao 2.º ponto de apalpação da 1.ª reta</translation>
    </message>
    <message>
        <source>Tolerance of the 2nd edge along its normal</source>
        <translation>Tolerância da 2.ª aresta ao longo da sua normal</translation>
    </message>
    <message>
        <source>Nominal angle of the 2nd line</source>
        <translation>Ângulo nominal da 2.ª reta</translation>
    </message>
    <message>
        <source>Probing direction of the 2nd line: +1 angle + 90, -1 - 90</source>
        <translation>Direção de apalpação da 2.ª reta: +1 ângulo + 90, -1 - 90</translation>
    </message>
    <message>
        <source>Intersection to the 1st touch point of the 2nd line</source>
        <translation>Distância do ponto de interseção ao 1.º ponto de apalpação da 2.ª reta</translation>
    </message>
    <message>
        <source>Intersection to the 2nd touch point of the 2nd line</source>
        <translation>Distância do ponto de interseção ao 2.º ponto de apalpação da 2.ª reta</translation>
    </message>
    <message>
        <source>Plane of the angles: 1 YZ, 2 ZX, 3 XY</source>
        <translation>Plano dos ângulos: 1 YZ, 2 ZX, 3 XY</translation>
    </message>
    <message>
        <source>Clearance height: -1 never, 0 cycle, 1 each edge, 2 each touch point</source>
        <translation>Altura segura: -1 nunca, 0 ciclo, 1 cada aresta, 2 cada ponto de apalpação</translation>
    </message>
    <message>
        <source>Tolerance error: 0 nothing, 1 stop, 2 stop on scrap only</source>
        <translation>Erro de tolerância: 0 nada, 1 paragem, 2 paragem só com peça rejeitada</translation>
    </message>
    <message>
        <source>Align rotary axes: 0 no, 1 MOVE, 2 TURN</source>
        <translation>Alinhar os eixos rotativos: 0 não, 1 MOVE, 2 TURN</translation>
    </message>
    <message>
        <source>Transfer position into the active preset: 0 no, 1 yes</source>
        <translation>Transferir a posição para o ponto de referência ativo: 0 não, 1 sim</translation>
    </message>
    <message>
        <source>Accept rotation: 0 no, 1/3/5 basic rotation from edge 1/2/mean</source>
        <translation>Aceitar a rotação: 0 não, 1/3/5 rotação básica da aresta 1/2/média</translation>
    </message>
    <message>
        <source>cycle {1}: aligning the rotary axes (Q1126) needs the rotation accepted (Q1121)</source>
        <translation>ciclo {1}: alinhar os eixos rotativos (Q1126) requer aceitar a rotação (Q1121)</translation>
    </message>
    <message>
        <source>cycle {1}: this machine has no rotary table axis to correct the rotation with</source>
        <translation>ciclo {1}: esta máquina não tem nenhum eixo de mesa rotativa para corrigir a rotação</translation>
    </message>
    <message>
        <source>cycle {1}: tolerance QS{2} = &quot;{3}&quot; is not &quot;upper-lower&quot; or a number</source>
        <translation>ciclo {1}: a tolerância QS{2} = &quot;{3}&quot; não é &quot;superior-inferior&quot; nem um número</translation>
    </message>
    <message>
        <source>cycle {1}: tolerance exceeded ({2})</source>
        <translation>ciclo {1}: tolerância excedida ({2})</translation>
    </message>
    <message>
        <source>PROBING INTERSECTION</source>
        <translation>APALPAR PONTO DE INTERSEÇÃO</translation>
    </message>
    <message>
        <source>2nd touch point, main axis</source>
        <translation>2.º ponto de apalpação, eixo principal</translation>
    </message>
    <message>
        <source>2nd touch point, secondary axis</source>
        <translation>2.º ponto de apalpação, eixo secundário</translation>
    </message>
    <message>
        <source>Preset rotation angle: angle of the reference line</source>
        <translation>Pré-definição do ângulo de rotação: ângulo da reta de referência</translation>
    </message>
    <message>
        <source>BASIC ROTATION</source>
        <translation>ROTAÇÃO BÁSICA</translation>
    </message>
    <message>
        <source>Centre in the main axis</source>
        <translation>Centro no eixo principal</translation>
    </message>
    <message>
        <source>Centre in the secondary axis</source>
        <translation>Centro no eixo secundário</translation>
    </message>
    <message>
        <source>Side length parallel to the main axis</source>
        <translation>Comprimento lateral paralelo ao eixo principal</translation>
    </message>
    <message>
        <source>Side length parallel to the secondary axis</source>
        <translation>Comprimento lateral paralelo ao eixo secundário</translation>
    </message>
    <message>
        <source>Touch point, main axis</source>
        <translation>Ponto de apalpação, eixo principal</translation>
    </message>
    <message>
        <source>Touch point, secondary axis</source>
        <translation>Ponto de apalpação, eixo secundário</translation>
    </message>
    <message>
        <source>Touch point, nominal surface in the tool axis</source>
        <translation>Ponto de apalpação, superfície nominal no eixo da ferramenta</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main, 2 secondary, 3 tool axis</source>
        <translation>Eixo de medição: 1 principal, 2 secundário, 3 eixo da ferramenta</translation>
    </message>
    <message>
        <source>New datum in the measuring axis</source>
        <translation>Novo ponto de referência no eixo de medição</translation>
    </message>
    <message>
        <source>DATUM INSIDE RECTANGLE</source>
        <translation>PONTO DE REFERÊNCIA RETÂNGULO INTERIOR</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE RECTANGLE</source>
        <translation>PONTO DE REFERÊNCIA RETÂNGULO EXTERIOR</translation>
    </message>
    <message>
        <source>DATUM INSIDE CIRCLE</source>
        <translation>PONTO DE REFERÊNCIA CÍRCULO INTERIOR</translation>
    </message>
    <message>
        <source>DATUM OUTSIDE CIRCLE</source>
        <translation>PONTO DE REFERÊNCIA CÍRCULO EXTERIOR</translation>
    </message>
    <message>
        <source>DATUM IN TS AXIS</source>
        <translation>PONTO DE REFERÊNCIA EIXO DO APALPADOR</translation>
    </message>
    <message>
        <source>DATUM IN ONE AXIS</source>
        <translation>PONTO DE REFERÊNCIA NUM EIXO</translation>
    </message>
    <message>
        <source>cycle {1}: define the measured-value transfer (Q303)</source>
        <translation>ciclo {1}: defina a transferência do valor medido (Q303)</translation>
    </message>
    <message>
        <source>Nominal centre, main axis</source>
        <translation>Centro nominal, eixo principal</translation>
    </message>
    <message>
        <source>Nominal centre, secondary axis</source>
        <translation>Centro nominal, eixo secundário</translation>
    </message>
    <message>
        <source>Maximum permitted diameter (0: not monitored)</source>
        <translation>Diâmetro máximo admissível (0: sem monitorização)</translation>
    </message>
    <message>
        <source>Minimum permitted diameter</source>
        <translation>Diâmetro mínimo admissível</translation>
    </message>
    <message>
        <source>Centre tolerance, main axis (0: not monitored)</source>
        <translation>Tolerância do centro, eixo principal (0: sem monitorização)</translation>
    </message>
    <message>
        <source>Centre tolerance, secondary axis</source>
        <translation>Tolerância do centro, eixo secundário</translation>
    </message>
    <message>
        <source>Compatibility only, no effect</source>
        <translation>Só para compatibilidade, sem efeito</translation>
    </message>
    <message>
        <source>Starting point, main axis</source>
        <translation>Ponto inicial, eixo principal</translation>
    </message>
    <message>
        <source>Starting point, secondary axis</source>
        <translation>Ponto inicial, eixo secundário</translation>
    </message>
    <message>
        <source>Offset before the second measurement (0: none)</source>
        <translation>Desvio antes da segunda medição (0: nenhum)</translation>
    </message>
    <message>
        <source>Nominal length</source>
        <translation>Comprimento nominal</translation>
    </message>
    <message>
        <source>Maximum permitted length (0: not monitored)</source>
        <translation>Comprimento máximo admissível (0: sem monitorização)</translation>
    </message>
    <message>
        <source>Minimum permitted length</source>
        <translation>Comprimento mínimo admissível</translation>
    </message>
    <message>
        <source>Nominal side length parallel to the main axis</source>
        <translation>Comprimento lateral nominal paralelo ao eixo principal</translation>
    </message>
    <message>
        <source>Nominal side length parallel to the secondary axis</source>
        <translation>Comprimento lateral nominal paralelo ao eixo secundário</translation>
    </message>
    <message>
        <source>Maximum length of side 1 (0: not monitored)</source>
        <translation>Comprimento máximo do lado 1 (0: sem monitorização)</translation>
    </message>
    <message>
        <source>Minimum length of side 1</source>
        <translation>Comprimento mínimo do lado 1</translation>
    </message>
    <message>
        <source>Maximum length of side 2 (0: not monitored)</source>
        <translation>Comprimento máximo do lado 2 (0: sem monitorização)</translation>
    </message>
    <message>
        <source>Minimum length of side 2</source>
        <translation>Comprimento mínimo do lado 2</translation>
    </message>
    <message>
        <source>Maximum permitted value (0 with Q289 = 0: not monitored)</source>
        <translation>Valor máximo admissível (0 com Q289 = 0: sem monitorização)</translation>
    </message>
    <message>
        <source>Minimum permitted value</source>
        <translation>Valor mínimo admissível</translation>
    </message>
    <message>
        <source>MEASURE ANGLE</source>
        <translation>MEDIR ÂNGULO</translation>
    </message>
    <message>
        <source>MEASURE RECTANGLE INSIDE</source>
        <translation>MEDIR RETÂNGULO INTERIOR</translation>
    </message>
    <message>
        <source>MEASURE RECTANGLE OUTSIDE</source>
        <translation>MEDIR RETÂNGULO EXTERIOR</translation>
    </message>
    <message>
        <source>MEASURE COORDINATE</source>
        <translation>MEDIR COORDENADA</translation>
    </message>
    <message>
        <source>MEASURE HOLE</source>
        <translation>MEDIR FURO</translation>
    </message>
    <message>
        <source>MEASURE CIRCLE OUTSIDE</source>
        <translation>MEDIR CÍRCULO EXTERIOR</translation>
    </message>
    <message>
        <source>MEASURE INSIDE WIDTH</source>
        <translation>MEDIR LARGURA INTERIOR</translation>
    </message>
    <message>
        <source>MEASURE RIDGE WIDTH</source>
        <translation>MEDIR LARGURA DA NERVURA</translation>
    </message>
    <message>
        <source>cycle {1}: stylus already deflected</source>
        <translation>ciclo {1}: a haste já está desviada</translation>
    </message>
    <message>
        <source>cycle {1}: touch point not reached within the measuring path DIST = {2} mm</source>
        <translation>ciclo {1}: ponto de apalpação não alcançado dentro do percurso de medição DIST = {2} mm</translation>
    </message>
    <message>
        <source>Measuring height: ball centre in the tool axis</source>
        <translation>Altura de medição: centro da esfera no eixo da ferramenta</translation>
    </message>
    <message>
        <source>Set-up clearance, added to SET_UP of the probe table</source>
        <translation>Distância de segurança, somada a SET_UP da tabela de apalpadores</translation>
    </message>
    <message>
        <source>Clearance height: no collision with workpiece or fixtures</source>
        <translation>Altura segura: sem colisão com a peça nem com os dispositivos de fixação</translation>
    </message>
    <message>
        <source>Move to clearance height between points: 0 no, 1 yes</source>
        <translation>Deslocar à altura segura entre pontos: 0 não, 1 sim</translation>
    </message>
    <message>
        <source>Number in table: 0 sets the display (active preset)</source>
        <translation>Número na tabela: 0 define a visualização (ponto de referência ativo)</translation>
    </message>
    <message>
        <source>Measured-value transfer: 0 datum table, 1 preset table</source>
        <translation>Transferência do valor medido: 0 tabela de pontos zero, 1 tabela de pontos de referência</translation>
    </message>
    <message>
        <source>New datum in the main axis</source>
        <translation>Novo ponto de referência no eixo principal</translation>
    </message>
    <message>
        <source>New datum in the secondary axis</source>
        <translation>Novo ponto de referência no eixo secundário</translation>
    </message>
    <message>
        <source>New datum in the tool axis</source>
        <translation>Novo ponto de referência no eixo da ferramenta</translation>
    </message>
    <message>
        <source>Probe in the tool axis too: 0 no, 1 yes</source>
        <translation>Apalpar também no eixo da ferramenta: 0 não, 1 sim</translation>
    </message>
    <message>
        <source>Tool-axis touch point, main axis</source>
        <translation>Ponto de apalpação no eixo da ferramenta, eixo principal</translation>
    </message>
    <message>
        <source>Tool-axis touch point, secondary axis</source>
        <translation>Ponto de apalpação no eixo da ferramenta, eixo secundário</translation>
    </message>
    <message>
        <source>Tool-axis touch point, nominal surface in the tool axis</source>
        <translation>Ponto de apalpação no eixo da ferramenta, superfície nominal no eixo da ferramenta</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main axis, 2 secondary axis</source>
        <translation>Eixo de medição: 1 eixo principal, 2 eixo secundário</translation>
    </message>
    <message>
        <source>Traverse direction toward the workpiece: -1 or +1</source>
        <translation>Direção de deslocação para a peça: -1 ou +1</translation>
    </message>
    <message>
        <source>Starting angle: main axis to touch point 1</source>
        <translation>Ângulo inicial: do eixo principal ao ponto de apalpação 1</translation>
    </message>
    <message>
        <source>Stepping angle between touch points (sign = direction)</source>
        <translation>Incremento angular entre os pontos de apalpação (sinal = direção)</translation>
    </message>
    <message>
        <source>Number of touch points in the plane: 3 or 4</source>
        <translation>Número de pontos de apalpação no plano: 3 ou 4</translation>
    </message>
    <message>
        <source>Path between points: 0 straight line, 1 arc</source>
        <translation>Trajetória entre pontos: 0 reta, 1 arco</translation>
    </message>
    <message>
        <source>Measuring log: 0 none, 1 write TCHPRnnn.TXT, 2 also stop</source>
        <translation>Protocolo de medição: 0 nenhum, 1 escrever TCHPRnnn.TXT, 2 também parar</translation>
    </message>
    <message>
        <source>PGM stop on tolerance error: 0 no, 1 yes</source>
        <translation>Paragem do PGM com erro de tolerância: 0 não, 1 sim</translation>
    </message>
    <message>
        <source>Tool for monitoring: 0 none</source>
        <translation>Ferramenta para monitorização: 0 nenhuma</translation>
    </message>
    <message>
        <source>PROBE expected after TCH</source>
        <translation>PROBE esperado depois de TCH</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: call the touch probe with TOOL CALL first (it defines the probe axis)</source>
        <translation>ciclo de apalpação {1}: chame primeiro o apalpador com TOOL CALL (define o eixo do apalpador)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: probe {2} is not in tchprobe.tp</source>
        <translation>ciclo de apalpação {1}: o apalpador {2} não está em tchprobe.tp</translation>
    </message>
    <message>
        <source>touch probe cycle {1} is not supported yet</source>
        <translation>o ciclo de apalpação {1} ainda não é suportado</translation>
    </message>
    <message>
        <source>{1}: Q{2} is PREDEF but GLOBAL DEF 120 gives no value</source>
        <translation>{1}: Q{2} é PREDEF, mas GLOBAL DEF 120 não dá nenhum valor</translation>
    </message>
    <message>
        <source>{1}: probing is not possible while a coordinate transformation is active (cycles 7, 8, 10, 11, 26)</source>
        <translation>{1}: não é possível apalpar enquanto estiver ativa uma conversão de coordenadas (ciclos 7, 8, 10, 11, 26)</translation>
    </message>
    <message>
        <source>{1}: probing runs with tool axis Z only so far</source>
        <translation>{1}: por enquanto a apalpação só funciona com o eixo da ferramenta Z</translation>
    </message>
    <message>
        <source>cannot write the measuring log {1}: {2}</source>
        <translation>não é possível escrever o protocolo de medição {1}: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the preset table: {2}</source>
        <translation>ciclo de apalpação {1}: não é possível escrever a tabela de pontos de referência: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1} is not supported yet; the program cannot run past this block</source>
        <translation>o ciclo de apalpação {1} ainda não é suportado; o programa não pode continuar para além deste bloco</translation>
    </message>
    <message>
        <source>{1} must be an array of three numbers [x, y, z], not {2}</source>
        <translation>{1} tem de ser uma lista de três números [x, y, z], não {2}</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine X; write shift = [x, y, z]</source>
        <translation>Simulação: quanto a peça bruta real se afasta da sua posição programada no X da máquina; escreva shift = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine Y; write shift = [x, y, z]</source>
        <translation>Simulação: quanto a peça bruta real se afasta da sua posição programada no Y da máquina; escreva shift = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank lies from its programmed position in machine Z; write shift = [x, y, z]</source>
        <translation>Simulação: quanto a peça bruta real se afasta da sua posição programada no Z da máquina; escreva shift = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulation: how far the real blank is turned about the tool axis, through its programmed origin</source>
        <translation>Simulação: quanto a peça bruta real está rodada em torno do eixo da ferramenta, através da sua origem programada</translation>
    </message>
    <message>
        <source>X of the start point</source>
        <translation>X do ponto inicial</translation>
    </message>
    <message>
        <source>Z of the start point</source>
        <translation>Z do ponto inicial</translation>
    </message>
    <message>
        <source>Program that holds the profile</source>
        <translation>Programa que contém o perfil</translation>
    </message>
    <message>
        <source>X of the end point</source>
        <translation>X do ponto final</translation>
    </message>
    <message>
        <source>Peck reduction factor (tapping: tapping type)</source>
        <translation>Fator de redução do passo de furação (roscagem: tipo de roscagem)</translation>
    </message>
    <message>
        <source>Z of the end point</source>
        <translation>Z do ponto final</translation>
    </message>
    <message>
        <source>Label of the first profile block</source>
        <translation>Etiqueta do primeiro bloco do perfil</translation>
    </message>
    <message>
        <source>Minimum infeed increment</source>
        <translation>Incremento mínimo de penetração</translation>
    </message>
    <message>
        <source>Label of the last profile block</source>
        <translation>Etiqueta do último bloco do perfil</translation>
    </message>
    <message>
        <source>Pass step</source>
        <translation>Passo de passagem</translation>
    </message>
    <message>
        <source>Maximum pass step</source>
        <translation>Passo máximo de passagem</translation>
    </message>
    <message>
        <source>Rapid approach to the previous peck</source>
        <translation>Aproximação rápida ao passo anterior</translation>
    </message>
    <message>
        <source>Thread pitch</source>
        <translation>Passo da rosca</translation>
    </message>
    <message>
        <source>Maximum step between plunges</source>
        <translation>Passo máximo entre penetrações</translation>
    </message>
    <message>
        <source>Stock to remove</source>
        <translation>Material a remover</translation>
    </message>
    <message>
        <source>X distance from the start point to the arc centre</source>
        <translation>Distância em X do ponto inicial ao centro do arco</translation>
    </message>
    <message>
        <source>Depth from the start point</source>
        <translation>Profundidade a partir do ponto inicial</translation>
    </message>
    <message>
        <source>Total thread depth</source>
        <translation>Profundidade total da rosca</translation>
    </message>
    <message>
        <source>Feed for plunging into valleys</source>
        <translation>Avanço de penetração nos vales</translation>
    </message>
    <message>
        <source>Z distance from the start point to the arc centre</source>
        <translation>Distância em Z do ponto inicial ao centro do arco</translation>
    </message>
    <message>
        <source>Measured point of a thread to repass</source>
        <translation>Ponto medido de uma rosca a repassar</translation>
    </message>
    <message>
        <source>Dwell at the bottom</source>
        <translation>Tempo de espera no fundo</translation>
    </message>
    <message>
        <source>Infeed angle</source>
        <translation>Ângulo de penetração</translation>
    </message>
    <message>
        <source>Main machining axis (0: Z, 1: X)</source>
        <translation>Eixo principal de maquinação (0: Z, 1: X)</translation>
    </message>
    <message>
        <source>Finishing allowance in X</source>
        <translation>Sobremetal de acabamento em X</translation>
    </message>
    <message>
        <source>Minimum peck depth</source>
        <translation>Passo mínimo de furação</translation>
    </message>
    <message>
        <source>Finishing pass allowance</source>
        <translation>Sobremetal da passagem de acabamento</translation>
    </message>
    <message>
        <source>Finishing allowance in Z</source>
        <translation>Sobremetal de acabamento em Z</translation>
    </message>
    <message>
        <source>Pitch change per revolution</source>
        <translation>Variação do passo por rotação</translation>
    </message>
    <message>
        <source>Rapid retract after each peck</source>
        <translation>Recuo rápido após cada passo</translation>
    </message>
    <message>
        <source>Feed of the finishing pass</source>
        <translation>Avanço da passagem de acabamento</translation>
    </message>
    <message>
        <source>Feed of the final roughing pass</source>
        <translation>Avanço da última passagem de desbaste</translation>
    </message>
    <message>
        <source>Safety distance from the thread start</source>
        <translation>Distância de segurança desde o início da rosca</translation>
    </message>
    <message>
        <source>Safety distance for the retract</source>
        <translation>Distância de segurança para o recuo</translation>
    </message>
    <message>
        <source>Peck depth (0: tapping)</source>
        <translation>Passo de furação (0: roscagem)</translation>
    </message>
    <message>
        <source>Depth of the first pass (negative: constant step)</source>
        <translation>Profundidade da primeira passagem (negativa: passo constante)</translation>
    </message>
    <message>
        <source>Thread run-out</source>
        <translation>Saída da rosca</translation>
    </message>
    <message>
        <source>Spindle angle at the start or measured point</source>
        <translation>Ângulo da árvore no ponto inicial ou medido</translation>
    </message>
    <message>
        <source>Number of thread starts</source>
        <translation>Número de entradas da rosca</translation>
    </message>
    <message>
        <source>One value per field</source>
        <translation>Um valor por campo</translation>
    </message>
    <message>
        <source>Canned
cycles</source>
        <translation>Ciclos
fixos</translation>
    </message>
    <message>
        <source>Put the cursor on a canned cycle block (G66-G89) to edit it.</source>
        <translation>Coloque o cursor num bloco de ciclo fixo (G66-G89) para o editar.</translation>
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
        <translation>Execução bloco a bloco</translation>
    </message>
    <message>
        <source>Automatic execution</source>
        <translation>Execução automática</translation>
    </message>
    <message>
        <source>Editing</source>
        <translation>Edição</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulação</translation>
    </message>
    <message>
        <source>Label numbers of the contour subprograms (up to 12, separated by /)</source>
        <translation>Números de label dos subprogramas de contorno (até 12, separados por /)</translation>
    </message>
    <message>
        <source>Inside corner rounding radius</source>
        <translation>Raio de arredondamento nos cantos interiores</translation>
    </message>
    <message>
        <source>CONTOUR</source>
        <translation>CONTORNO</translation>
    </message>
    <message>
        <source>CONTOUR DATA</source>
        <translation>DADOS DO CONTORNO</translation>
    </message>
    <message>
        <source>Rough-out tool number (0: the tool in the spindle)</source>
        <translation>Número da ferramenta de desbaste (0: a ferramenta na árvore)</translation>
    </message>
    <message>
        <source>cycle {1} needs a pocket among the contours of cycle 14</source>
        <translation>o ciclo {1} precisa de uma caixa entre os contornos do ciclo 14</translation>
    </message>
    <message>
        <source>cycle {1}: tool {2} ({3}) is not in the tool table</source>
        <translation>ciclo {1}: a ferramenta {2} ({3}) não está na tabela de ferramentas</translation>
    </message>
    <message>
        <source>PILOT DRILLING</source>
        <translation>PRÉ-FURAR</translation>
    </message>
    <message>
        <source>Coarse roughing tool number (0: none)</source>
        <translation>Número da ferramenta de desbaste prévio (0: nenhuma)</translation>
    </message>
    <message>
        <source>Feed rate for reciprocation</source>
        <translation>Avanço de pendular</translation>
    </message>
    <message>
        <source>Feed rate factor in %</source>
        <translation>Fator de avanço em %</translation>
    </message>
    <message>
        <source>Fine roughing strategy (0 along the contour, 1 retract between areas)</source>
        <translation>Estratégia de desbaste fino (0 ao longo do contorno, 1 retrair entre áreas)</translation>
    </message>
    <message>
        <source>cycle {1}: the feed rate for reciprocation Q19 needs the plunge angle ANGLE of the tool</source>
        <translation>ciclo {1}: o avanço de pendular Q19 precisa do ângulo de penetração ANGLE da ferramenta</translation>
    </message>
    <message>
        <source>ROUGH-OUT</source>
        <translation>DESBASTAR</translation>
    </message>
    <message>
        <source>FLOOR FINISHING</source>
        <translation>ACABAMENTO EM PROFUNDIDADE</translation>
    </message>
    <message>
        <source>SIDE FINISHING</source>
        <translation>ACABAMENTO LATERAL</translation>
    </message>
    <message>
        <source>cycle {1} needs cycle 20 CONTOUR DATA before it</source>
        <translation>o ciclo {1} precisa antes do ciclo 20 DADOS DO CONTORNO</translation>
    </message>
    <message>
        <source>cycle {1} needs cycle 14 CONTOUR before it</source>
        <translation>o ciclo {1} precisa antes do ciclo 14 CONTORNO</translation>
    </message>
    <message>
        <source>cycle {1}: the islands of cycle 14 cover the whole pocket</source>
        <translation>ciclo {1}: as ilhas do ciclo 14 cobrem a caixa inteira</translation>
    </message>
    <message>
        <source>Retraction feed rate (0: milling feed)</source>
        <translation>Avanço de retrocesso (0: avanço de fresagem)</translation>
    </message>
    <message>
        <source>cycle 14: a label number from 1 to 65535 expected</source>
        <translation>ciclo 14: esperado um número de label de 1 a 65535</translation>
    </message>
    <message>
        <source>cycle 14: label numbers are separated by &apos;/&apos;</source>
        <translation>ciclo 14: os números de label são separados por &apos;/&apos;</translation>
    </message>
    <message>
        <source>cycle 14 lists 1 to 12 label numbers</source>
        <translation>o ciclo 14 lista de 1 a 12 números de label</translation>
    </message>
    <message>
        <source>this block is not allowed in a contour subprogram</source>
        <translation>este bloco não é permitido num subprograma de contorno</translation>
    </message>
    <message>
        <source>a contour subprogram must not move in the tool axis</source>
        <translation>um subprograma de contorno não deve deslocar no eixo da ferramenta</translation>
    </message>
    <message>
        <source>the first block of a contour subprogram must be a straight line with both working-plane axes</source>
        <translation>o primeiro bloco de um subprograma de contorno deve ser uma reta com os dois eixos do plano de maquinagem</translation>
    </message>
    <message>
        <source>a contour subprogram has more than 16384 blocks</source>
        <translation>um subprograma de contorno tem mais de 16384 blocos</translation>
    </message>
    <message>
        <source>the contour subprogram LBL {1} needs radius compensation RL or RR (pocket or island)</source>
        <translation>o subprograma de contorno LBL {1} precisa de correção de raio RL ou RR (caixa ou ilha)</translation>
    </message>
    <message>
        <source>MILLING DEPTH</source>
        <translation>PROFUNDIDADE FRESAR</translation>
    </message>
    <message>
        <source>TOOL PATH OVERLAP</source>
        <translation>SOBREPOSICAO TRAJ.</translation>
    </message>
    <message>
        <source>CLEARANCE HEIGHT</source>
        <translation>ALTURA DE SEGURANCA</translation>
    </message>
    <message>
        <source>ROUNDING RADIUS</source>
        <translation>RAIO ARREDONDAMENTO</translation>
    </message>
    <message>
        <source>ROTATIONAL DIRECTION</source>
        <translation>SENTIDO DE ROTACAO</translation>
    </message>
    <message>
        <source>FEED RATE F. ROUGHNG</source>
        <translation>AVANCO DESBASTE</translation>
    </message>
    <message>
        <source>ROUGH-OUT TOOL</source>
        <translation>FERRAM. DESBASTE</translation>
    </message>
    <message>
        <source>COARSE ROUGHING TOOL</source>
        <translation>FERRAM. PRE-DESBASTE</translation>
    </message>
    <message>
        <source>FEED RATE FOR RECIP.</source>
        <translation>AVANCO PENDULAR</translation>
    </message>
    <message>
        <source>FINE ROUGH STRATEGY</source>
        <translation>ESTRAT. DESB. FINO</translation>
    </message>
    <message>
        <source>after G00 the raw-stock profile needs G01, G02 or G03</source>
        <translation>após G00 o perfil do material bruto precisa de G01, G02 ou G03</translation>
    </message>
    <message>
        <source>An ISO block is either absolute (G90) or incremental (G91): enter all coordinates with I or none</source>
        <translation>Um bloco ISO é absoluto (G90) ou incremental (G91): introduza todas as coordenadas com I ou nenhuma</translation>
    </message>
    <message>
        <source>ISO programs have no FAUTO: enter the feed</source>
        <translation>Os programas ISO não têm FAUTO: introduza o avanço</translation>
    </message>
    <message>
        <source>This cycle has no ISO form</source>
        <translation>Este ciclo não tem forma ISO</translation>
    </message>
    <message>
        <source>This block has no ISO form</source>
        <translation>Este bloco não tem forma ISO</translation>
    </message>
    <message>
        <source>FK: the relative data refer to block {1}, which is not among the last 64 determined blocks</source>
        <translation>FK: os dados relativos referem-se ao bloco {1}, que não está entre os últimos 64 blocos determinados</translation>
    </message>
    <message>
        <source>FK: polar data need a pole FPOL</source>
        <translation>FK: os dados polares precisam de um polo FPOL</translation>
    </message>
    <message>
        <source>FK: this element has {1} solutions: choose one with FSELECT in the next block</source>
        <translation>FK: este elemento tem {1} soluções: escolha uma com FSELECT no bloco seguinte</translation>
    </message>
    <message>
        <source>FK: R and LEN must be positive, D must not be negative</source>
        <translation>FK: R e LEN têm de ser positivos, D não pode ser negativo</translation>
    </message>
    <message>
        <source>FK: CLSD- without a CLSD+ before it</source>
        <translation>FK: CLSD- sem um CLSD+ antes</translation>
    </message>
    <message>
        <source>FSELECT without an FK element with several solutions before it</source>
        <translation>FSELECT sem um elemento FK com várias soluções antes</translation>
    </message>
    <message>
        <source>FSELECT {1}: the element has {2} solutions</source>
        <translation>FSELECT {1}: o elemento tem {2} soluções</translation>
    </message>
    <message>
        <source>FK: this element is not determined: the FK sequence ends before enough data are given</source>
        <translation>FK: este elemento não está determinado: a sequência FK termina antes de haver dados suficientes</translation>
    </message>
    <message>
        <source>FK: this element is not determined by the blocks that follow it</source>
        <translation>FK: os blocos seguintes não determinam este elemento</translation>
    </message>
    <message>
        <source>FK: the data of this block contradict the contour: no solution</source>
        <translation>FK: os dados deste bloco contradizem o contorno: sem solução</translation>
    </message>
    <message>
        <source>FSELECT needs the number of a solution (1 to 99)</source>
        <translation>FSELECT precisa do número de uma solução (1 a 99)</translation>
    </message>
    <message>
        <source>unexpected text</source>
        <translation>texto inesperado</translation>
    </message>
    <message>
        <source>FPOL takes X and Y once each</source>
        <translation>FPOL aceita X e Y uma vez cada</translation>
    </message>
    <message>
        <source>FPOL needs X and Y</source>
        <translation>FPOL precisa de X e Y</translation>
    </message>
    <message>
        <source>this FK datum is programmed twice</source>
        <translation>este dado FK está programado duas vezes</translation>
    </message>
    <message>
        <source>CLSD+ or CLSD- expected</source>
        <translation>esperava-se CLSD+ ou CLSD-</translation>
    </message>
    <message>
        <source>the block number relative data refer to expected</source>
        <translation>esperava-se o número do bloco a que os dados relativos se referem</translation>
    </message>
    <message>
        <source>unexpected &apos;{1}&apos; in an FK block</source>
        <translation>&apos;{1}&apos; inesperado num bloco FK</translation>
    </message>
    <message>
        <source>P{1}X and P{1}Y are given together</source>
        <translation>P{1}X e P{1}Y indicam-se em conjunto</translation>
    </message>
    <message>
        <source>{1} needs an incremental value {2} in the same block</source>
        <translation>{1} precisa de um valor incremental {2} no mesmo bloco</translation>
    </message>
    <message>
        <source>1st touch point, nominal surface in the tool axis</source>
        <translation>1.º ponto de apalpação, superfície nominal no eixo da ferramenta</translation>
    </message>
    <message>
        <source>2nd touch point, nominal surface in the tool axis</source>
        <translation>2.º ponto de apalpação, superfície nominal no eixo da ferramenta</translation>
    </message>
    <message>
        <source>3rd touch point, nominal surface in the tool axis</source>
        <translation>3.º ponto de apalpação, superfície nominal no eixo da ferramenta</translation>
    </message>
    <message>
        <source>cycle {1}: the three touch points lie on one line</source>
        <translation>ciclo {1}: os três pontos de apalpação estão numa reta</translation>
    </message>
    <message>
        <source>MEASURE BOLT HOLE CIRC</source>
        <translation>MEDIR CIRC FUROS</translation>
    </message>
    <message>
        <source>MEASURE PLANE</source>
        <translation>MEDIR PLANO</translation>
    </message>
    <message>
        <source>1st centre, main axis</source>
        <translation>1.º centro, eixo principal</translation>
    </message>
    <message>
        <source>1st centre, secondary axis</source>
        <translation>1.º centro, eixo secundário</translation>
    </message>
    <message>
        <source>2nd centre, main axis</source>
        <translation>2.º centro, eixo principal</translation>
    </message>
    <message>
        <source>2nd centre, secondary axis</source>
        <translation>2.º centro, eixo secundário</translation>
    </message>
    <message>
        <source>Compensation: 0 basic rotation, 1 rotary table</source>
        <translation>Compensação: 0 rotação básica, 1 mesa rotativa</translation>
    </message>
    <message>
        <source>Set the rotary axis display to 0 after alignment: 0 no, 1 yes</source>
        <translation>Pôr a 0 a visualização do eixo rotativo após o alinhamento: 0 não, 1 sim</translation>
    </message>
    <message>
        <source>Diameter of stud 1 (rather too large)</source>
        <translation>Diâmetro da ilha 1 (de preferência demasiado grande)</translation>
    </message>
    <message>
        <source>Diameter of stud 2 (rather too large)</source>
        <translation>Diâmetro da ilha 2 (de preferência demasiado grande)</translation>
    </message>
    <message>
        <source>Measuring height at stud 2: ball centre in the tool axis</source>
        <translation>Altura de medição na ilha 2: centro da esfera no eixo da ferramenta</translation>
    </message>
    <message>
        <source>3rd centre, main axis</source>
        <translation>3.º centro, eixo principal</translation>
    </message>
    <message>
        <source>3rd centre, secondary axis</source>
        <translation>3.º centro, eixo secundário</translation>
    </message>
    <message>
        <source>4th centre, main axis</source>
        <translation>4.º centro, eixo principal</translation>
    </message>
    <message>
        <source>4th centre, secondary axis</source>
        <translation>4.º centro, eixo secundário</translation>
    </message>
    <message>
        <source>ROT 2 HOLES</source>
        <translation>ROT 2 FUROS</translation>
    </message>
    <message>
        <source>ROT 2 STUDS</source>
        <translation>ROT 2 ILHAS</translation>
    </message>
    <message>
        <source>DATUM FROM 4 HOLES</source>
        <translation>PONTO REF 4 FUROS</translation>
    </message>
    <message>
        <source>Width of the slot or ridge, whatever its orientation</source>
        <translation>Largura da ranhura ou da nervura, seja qual for a sua orientação</translation>
    </message>
    <message>
        <source>New datum in the measuring axis for the centre</source>
        <translation>Novo ponto de referência no eixo de medição para o centro</translation>
    </message>
    <message>
        <source>SLOT CENTER REF PT</source>
        <translation>PTO.REF.CENTRO RAN.</translation>
    </message>
    <message>
        <source>RIDGE CENTER REF PT</source>
        <translation>PTO.REF.CENTRO NERVURA</translation>
    </message>
    <message>
        <source>Tool measurement: 0 write L/R, 1 compare and write DL/DR, 2 compare</source>
        <translation>Medição da ferramenta: 0 escrever L/R, 1 comparar e escrever DL/DR, 2 comparar</translation>
    </message>
    <message>
        <source>Probe each tooth: 0 no, 1 yes</source>
        <translation>Apalpar cada dente: 0 não, 1 sim</translation>
    </message>
    <message>
        <source>CALIBRATE TT</source>
        <translation>CALIBRACAO TT</translation>
    </message>
    <message>
        <source>TOOL LENGTH</source>
        <translation>COMPR. FERRAMENTA</translation>
    </message>
    <message>
        <source>TOOL RADIUS</source>
        <translation>RAIO FERRAMENTA</translation>
    </message>
    <message>
        <source>MEASURE TOOL</source>
        <translation>MEDIR FERRAMENTA</translation>
    </message>
    <message>
        <source>TCH PROBE {1}.{2} without TCH PROBE {1}.0 before it</source>
        <translation>TCH PROBE {1}.{2} sem TCH PROBE {1}.0 antes</translation>
    </message>
    <message>
        <source>{1}.{2}: a number after &apos;:&apos; expected</source>
        <translation>{1}.{2}: espera-se um número após &apos;:&apos;</translation>
    </message>
    <message>
        <source>{1}: sub-blocks .1, .2 and .3 are needed</source>
        <translation>{1}: são necessários os blocos parciais .1, .2 e .3</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the machine has no tool touch probe ([simulation.tool_probe] enabled = true)</source>
        <translation>ciclo de apalpação {1}: a máquina não tem apalpador de ferramenta ([simulation.tool_probe] enabled = true)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: tool measurement is not possible while mirroring or scaling is active (cycles 8, 11, 26)</source>
        <translation>ciclo de apalpação {1}: a medição da ferramenta não é possível com espelho ou fator de escala ativos (ciclos 8, 11, 26)</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: probing runs with tool axis Z only so far</source>
        <translation>ciclo de apalpação {1}: por enquanto a apalpação só funciona com o eixo da ferramenta Z</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: call the tool to be measured from the tool table TOOL.T with TOOL CALL first</source>
        <translation>ciclo de apalpação {1}: chame primeiro com TOOL CALL a ferramenta a medir da tabela TOOL.T</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the tool table: {2}</source>
        <translation>ciclo de apalpação {1}: não é possível escrever a tabela de ferramentas: {2}</translation>
    </message>
    <message>
        <source>{1} must be tables [[{1}]] with tool, length and radius</source>
        <translation>{1} têm de ser tabelas [[{1}]] com tool, length e radius</translation>
    </message>
    <message>
        <source>{1} = {2} is out of range: a tool number 0 ... 32767, lengths within +-10 mm</source>
        <translation>{1} = {2} está fora do intervalo: um número de ferramenta 0 ... 32767, comprimentos dentro de +-10 mm</translation>
    </message>
    <message>
        <source>{1} needs a tool number</source>
        <translation>{1} precisa de um número de ferramenta</translation>
    </message>
    <message>
        <source>{1}: tool {2} is given twice</source>
        <translation>{1}: a ferramenta {2} está indicada duas vezes</translation>
    </message>
    <message>
        <source>Simulation: the machine has a tool touch probe (TT) for the tool measuring cycles 30-33 and 480-483</source>
        <translation>Simulação: a máquina tem um apalpador de ferramenta (TT) para os ciclos de medição de ferramenta 30-33 e 480-483</translation>
    </message>
    <message>
        <source>TT: machine X of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: X de máquina do centro da superfície de medição; escreva centre = [x, y, z]</translation>
    </message>
    <message>
        <source>TT: machine Y of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: Y de máquina do centro da superfície de medição; escreva centre = [x, y, z]</translation>
    </message>
    <message>
        <source>TT: machine Z of the centre of the measuring surface; write centre = [x, y, z]</source>
        <translation>TT: Z de máquina do centro da superfície de medição; escreva centre = [x, y, z]</translation>
    </message>
    <message>
        <source>TT: diameter of the disc stylus (side of a cube stylus)</source>
        <translation>TT: diâmetro da haste de disco (lado de uma haste cúbica)</translation>
    </message>
    <message>
        <source>TT: stylus shape, a disc or a cube</source>
        <translation>TT: forma da haste, disco ou cubo</translation>
    </message>
    <message>
        <source>TT: how far below the top of the stylus the end face of the tool sits when its radius is measured</source>
        <translation>TT: a que distância abaixo do topo da haste fica a face frontal da ferramenta ao medir o seu raio</translation>
    </message>
    <message>
        <source>TT: safety zone above the stylus, and how far before the stylus each touch starts</source>
        <translation>TT: zona de segurança acima da haste, e a que distância dela começa cada apalpação</translation>
    </message>
    <message>
        <source>TT: highest cutting-edge speed of a rotating tool; sets the measuring speed</source>
        <translation>TT: velocidade de corte máxima de uma ferramenta em rotação; define a velocidade de medição</translation>
    </message>
    <message>
        <source>TT: measuring error allowed with a rotating tool; probing feed = tolerance x speed</source>
        <translation>TT: erro de medição admissível com a ferramenta em rotação; avanço de apalpação = tolerância x velocidade</translation>
    </message>
    <message>
        <source>TT: probing feed with a stationary spindle</source>
        <translation>TT: avanço de apalpação com a árvore parada</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the tool to monitor (Q330 = {2}) is not in the tool table</source>
        <translation>ciclo de apalpação {1}: a ferramenta a supervisionar (Q330 = {2}) não está na tabela de ferramentas</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: tool {2} is broken (deviation {3} mm beyond RBREAK); it is locked</source>
        <translation>ciclo de apalpação {1}: a ferramenta {2} está partida (desvio {3} mm acima de RBREAK); fica bloqueada</translation>
    </message>
    <message>
        <source>Climb or up-cut (+1 climb, -1 up-cut, 0 alternating)</source>
        <translation>Fresagem sincronizada ou em contramarcha (+1 sincronizada, -1 contramarcha, 0 alternada)</translation>
    </message>
    <message>
        <source>Accepted residual material</source>
        <translation>Material residual aceite</translation>
    </message>
    <message>
        <source>Maximum connection distance</source>
        <translation>Distância máxima de ligação</translation>
    </message>
    <message>
        <source>Path extension</source>
        <translation>Prolongamento da trajetória</translation>
    </message>
    <message>
        <source>cycle {1}: with cycle 270 the contour subprogram must be programmed without RL/RR (Q391 gives the side)</source>
        <translation>ciclo {1}: com o ciclo 270 o subprograma de contorno deve ser programado sem RL/RR (Q391 define o lado)</translation>
    </message>
    <message>
        <source>CONTOUR TRAIN</source>
        <translation>TRAÇADO DE CONTORNO</translation>
    </message>
    <message>
        <source>Type of approach/departure (1 arc, 2 tangent line, 3 perpendicular)</source>
        <translation>Tipo de aproximação/saída (1 arco, 2 reta tangencial, 3 perpendicular)</translation>
    </message>
    <message>
        <source>Radius compensation (0 R0, 1 RL, 2 RR)</source>
        <translation>Correção do raio (0 R0, 1 RL, 2 RR)</translation>
    </message>
    <message>
        <source>Radius of the approach/departure arc</source>
        <translation>Raio do arco de aproximação/saída</translation>
    </message>
    <message>
        <source>Centre angle of the approach/departure arc</source>
        <translation>Ângulo central do arco de aproximação/saída</translation>
    </message>
    <message>
        <source>Distance of the auxiliary point</source>
        <translation>Distância do ponto auxiliar</translation>
    </message>
    <message>
        <source>CONTOUR TRAIN DATA</source>
        <translation>DADOS DE TRAÇADO DE CONTORNO</translation>
    </message>
    <message>
        <source>cycle {1}: cycle 14 must list exactly one contour subprogram (the slot&apos;s centre line)</source>
        <translation>ciclo {1}: o ciclo 14 deve indicar exatamente um subprograma de contorno (a linha central da ranhura)</translation>
    </message>
    <message>
        <source>cycle {1}: the start point of a closed slot must not lie on a corner of the contour</source>
        <translation>ciclo {1}: o ponto inicial de uma ranhura fechada não pode estar sobre uma esquina do contorno</translation>
    </message>
    <message>
        <source>cycle {1}: the plunging depth Q202 must be greater than 0</source>
        <translation>ciclo {1}: a profundidade de passo Q202 deve ser maior que 0</translation>
    </message>
    <message>
        <source>cycle {1}: the slot width less the side allowances is more than twice the tool diameter</source>
        <translation>ciclo {1}: a largura da ranhura menos os sobre-metais laterais é maior que o dobro do diâmetro da ferramenta</translation>
    </message>
    <message>
        <source>cycle {1}: the infeed per revolution Q436 must be greater than 0</source>
        <translation>ciclo {1}: o avanço por rotação Q436 deve ser maior que 0</translation>
    </message>
    <message>
        <source>Infeed per revolution (trochoidal loop)</source>
        <translation>Avanço por rotação (laço trocoidal)</translation>
    </message>
    <message>
        <source>Plunging strategy (0 vertical, 1 no function, 2 reciprocating)</source>
        <translation>Estratégia de afundamento (0 perpendicular, 1 sem função, 2 pendular)</translation>
    </message>
    <message>
        <source>TROCHOIDAL SLOT</source>
        <translation>RANHURA DE CONTORNO TROCOIDAL</translation>
    </message>
    <message>
        <source>Strategy (0 meander outside, 1 meander on the edge, 2 line by line, 3 line by line to the edge, 4 spiral)</source>
        <translation>Estratégia (0 meandro fora, 1 meandro na aresta, 2 linha a linha, 3 linha a linha até à aresta, 4 espiral)</translation>
    </message>
    <message>
        <source>Milling direction (1 main axis, 2 secondary axis)</source>
        <translation>Direção de fresagem (1 eixo principal, 2 eixo secundário)</translation>
    </message>
    <message>
        <source>1st limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>1.º limite (0 nenhum, -1/+1 eixo principal, -2/+2 eixo secundário)</translation>
    </message>
    <message>
        <source>2nd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>2.º limite (0 nenhum, -1/+1 eixo principal, -2/+2 eixo secundário)</translation>
    </message>
    <message>
        <source>3rd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)</source>
        <translation>3.º limite (0 nenhum, -1/+1 eixo principal, -2/+2 eixo secundário)</translation>
    </message>
    <message>
        <source>Corner radius</source>
        <translation>Raio de esquina</translation>
    </message>
    <message>
        <source>cycle {1}: limits Q347-Q349 are not possible with the spiral strategy Q389 = 4</source>
        <translation>ciclo {1}: os limites Q347-Q349 não são possíveis com a estratégia em espiral Q389 = 4</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is too large for the face between its walls</source>
        <translation>ciclo {1}: a ferramenta é demasiado grande para a superfície entre as suas paredes</translation>
    </message>
    <message>
        <source>1ST LIMIT</source>
        <translation>1. LIMITE</translation>
    </message>
    <message>
        <source>2ND LIMIT</source>
        <translation>2. LIMITE</translation>
    </message>
    <message>
        <source>3RD LIMIT</source>
        <translation>3. LIMITE</translation>
    </message>
    <message>
        <source>MILLING DIRECTION</source>
        <translation>DIREÇÃO FRESAGEM</translation>
    </message>
    <message>
        <source>TYPE OF APPROACH</source>
        <translation>TIPO APROXIMAÇÃO</translation>
    </message>
    <message>
        <source>RADIUS COMPENSATION</source>
        <translation>CORREÇÃO RAIO</translation>
    </message>
    <message>
        <source>RADIUS</source>
        <translation>RAIO</translation>
    </message>
    <message>
        <source>CENTER ANGLE</source>
        <translation>ÂNGULO CENTRAL</translation>
    </message>
    <message>
        <source>DISTANCE</source>
        <translation>DISTÂNCIA</translation>
    </message>
    <message>
        <source>INFEED PER REV.</source>
        <translation>AVANÇO POR ROTAÇÃO</translation>
    </message>
    <message>
        <source>RESIDUAL MATERIAL</source>
        <translation>MATERIAL RESIDUAL</translation>
    </message>
    <message>
        <source>CONNECTION DISTANCE</source>
        <translation>DISTÂNCIA LIGAÇÃO</translation>
    </message>
    <message>
        <source>PATH EXTENSION</source>
        <translation>PROLONG. TRAJETÓRIA</translation>
    </message>
    <message>
        <source>MILLING STRATEGY</source>
        <translation>ESTRATÉGIA FRESAGEM</translation>
    </message>
    <message>
        <source>cycle {1}: cycle 14 must list exactly one contour subprogram</source>
        <translation>ciclo {1}: o ciclo 14 deve indicar exatamente um subprograma de contorno</translation>
    </message>
    <message>
        <source>cycle {1}: the tool is below the clearance height Q7 at the call</source>
        <translation>ciclo {1}: a ferramenta está abaixo da altura segura Q7 na chamada</translation>
    </message>
    <message>
        <source>3-D CONTOUR TRAIN</source>
        <translation>TRAÇADO DO CONTORNO 3D</translation>
    </message>
    <message>
        <source>the first block of a 3-D contour subprogram must give the tool axis too</source>
        <translation>o primeiro bloco de um subprograma de contorno 3D também deve indicar o eixo da ferramenta</translation>
    </message>
    <message>
        <source>PLANE: SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL or RESET expected</source>
        <translation>PLANE: esperado SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL ou RESET</translation>
    </message>
    <message>
        <source>PLANE {1}: {2} expected</source>
        <translation>PLANE {1}: esperado {2}</translation>
    </message>
    <message>
        <source>PLANE RELATIV: SPA, SPB or SPC expected</source>
        <translation>PLANE RELATIV: esperado SPA, SPB ou SPC</translation>
    </message>
    <message>
        <source>PLANE AXIAL: an angle of A, B or C expected</source>
        <translation>PLANE AXIAL: esperado um ângulo de A, B ou C</translation>
    </message>
    <message>
        <source>SEQ+ or SEQ- expected</source>
        <translation>esperado SEQ+ ou SEQ-</translation>
    </message>
    <message>
        <source>ROT expected</source>
        <translation>esperado ROT</translation>
    </message>
    <message>
        <source>PLANE: unexpected &apos;{1}&apos;</source>
        <translation>PLANE: &apos;{1}&apos; inesperado</translation>
    </message>
    <message>
        <source>PLANE: MOVE, TURN or STAY expected</source>
        <translation>PLANE: esperado MOVE, TURN ou STAY</translation>
    </message>
    <message>
        <source>PLANE: the points or vectors do not define a plane</source>
        <translation>PLANE: os pontos ou vetores não definem um plano</translation>
    </message>
    <message>
        <source>{1} needs rotary axes: this machine has none</source>
        <translation>{1} precisa de eixos rotativos: esta máquina não tem nenhum</translation>
    </message>
    <message>
        <source>{1} needs the rotary tables described in the machine file ([kinematics], docs/machine-config.md)</source>
        <translation>{1} precisa das mesas rotativas descritas no ficheiro da máquina ([kinematics], docs/machine-config.md)</translation>
    </message>
    <message>
        <source>the rotary axes of this machine cannot turn the tool perpendicular to this plane</source>
        <translation>os eixos rotativos desta máquina não conseguem pôr a ferramenta perpendicular a este plano</translation>
    </message>
    <message>
        <source>no solution for the rotary axes lies within their soft limits (and the SEQ chosen): {1}</source>
        <translation>nenhuma solução para os eixos rotativos fica dentro dos seus limites de software (e do SEQ escolhido): {1}</translation>
    </message>
    <message>
        <source>PLANE with radius compensation RL/RR: program R0 first</source>
        <translation>PLANE com correção de raio RL/RR: programe R0 primeiro</translation>
    </message>
    <message>
        <source>cycle 19: unexpected &apos;{1}&apos;</source>
        <translation>ciclo 19: &apos;{1}&apos; inesperado</translation>
    </message>
    <message>
        <source>the move would take axis {1} to {2} deg (machine coordinates), beyond its soft limit {3}</source>
        <translation>o movimento levaria o eixo {1} a {2} graus (coordenadas da máquina), além do seu limite de software {3}</translation>
    </message>
    <message>
        <source>Machine X where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>X da máquina onde os eixos rotativos se cruzam; escreva pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Machine Y where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>Y da máquina onde os eixos rotativos se cruzam; escreva pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Machine Z where the rotary axes meet; write pivot = [x, y, z]</source>
        <translation>Z da máquina onde os eixos rotativos se cruzam; escreva pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Rotary: turns without end; no soft limits, M126 takes the short way</source>
        <translation>Rotativo: roda sem fim; sem limites de software, M126 segue o caminho curto</translation>
    </message>
    <message>
        <source>{1} = true is only allowed on a rotary axis</source>
        <translation>{1} = true só é permitido num eixo rotativo</translation>
    </message>
    <message>
        <source>{1} = &quot;{2}&quot; is not an enabled rotary axis of this machine</source>
        <translation>{1} = &quot;{2}&quot; não é um eixo rotativo ativo desta máquina</translation>
    </message>
    <message>
        <source>kinematics.secondary must be another axis than kinematics.primary</source>
        <translation>kinematics.secondary tem de ser outro eixo que kinematics.primary</translation>
    </message>
    <message>
        <source>P{1} expected after G18</source>
        <translation>esperado P{1} após G18</translation>
    </message>
    <message>
        <source>Show
solution</source>
        <translation>Mostrar
solução</translation>
    </message>
    <message>
        <source>Select
solution</source>
        <translation>Selecionar
solução</translation>
    </message>
    <message>
        <source>cycle {1}: the contour formula leaves no area to machine</source>
        <translation>ciclo {1}: a fórmula de contorno não deixa nenhuma área para maquinar</translation>
    </message>
    <message>
        <source>parentheses nested too deep</source>
        <translation>parênteses aninhados demasiado profundamente</translation>
    </message>
    <message>
        <source>a contour descriptor QC1 ... QC65535 or &apos;(&apos; expected</source>
        <translation>esperado um descritor de contorno QC1 ... QC65535 ou &apos;(&apos;</translation>
    </message>
    <message>
        <source>program name in quotes expected</source>
        <translation>esperado o nome do programa entre aspas</translation>
    </message>
    <message>
        <source>DEPTH value expected</source>
        <translation>esperado um valor para DEPTH</translation>
    </message>
    <message>
        <source>unexpected text &apos;{1}&apos;</source>
        <translation>texto inesperado &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>a contour descriptor QC1 ... QC65535 expected</source>
        <translation>esperado um descritor de contorno QC1 ... QC65535</translation>
    </message>
    <message>
        <source>pocket P1 ... P9 or island I1 ... I9 expected</source>
        <translation>esperada uma caixa P1 ... P9 ou uma ilha I1 ... I9</translation>
    </message>
    <message>
        <source>CONTOUR DEF combines at most 9 subcontours</source>
        <translation>CONTOUR DEF combina no máximo 9 subcontornos</translation>
    </message>
    <message>
        <source>the first subcontour of CONTOUR DEF must be a pocket (P)</source>
        <translation>o primeiro subcontorno de CONTOUR DEF tem de ser uma caixa (P)</translation>
    </message>
    <message>
        <source>CONTOUR DEF needs a pocket P1 = &quot;program&quot;</source>
        <translation>CONTOUR DEF precisa de uma caixa P1 = &quot;programa&quot;</translation>
    </message>
    <message>
        <source>a contour formula combines at most 128 contours</source>
        <translation>uma fórmula de contorno combina no máximo 128 contornos</translation>
    </message>
    <message>
        <source>QC{1} is not declared (DECLARE CONTOUR)</source>
        <translation>QC{1} não está declarado (DECLARE CONTOUR)</translation>
    </message>
    <message>
        <source>the contour formula is too long</source>
        <translation>a fórmula de contorno é demasiado longa</translation>
    </message>
    <message>
        <source>cannot read the contour program {1}: {2}</source>
        <translation>não é possível ler o programa de contorno {1}: {2}</translation>
    </message>
    <message>
        <source>the contour program {1} has errors</source>
        <translation>o programa de contorno {1} contém erros</translation>
    </message>
    <message>
        <source>this block is not allowed in a contour-definition program</source>
        <translation>este bloco não é permitido num programa de definição de contorno</translation>
    </message>
    <message>
        <source>every contour needs a DEPTH when one has it (DEPTH0: the depth of cycle 20)</source>
        <translation>cada contorno precisa de DEPTH quando um o tem (DEPTH0: a profundidade do ciclo 20)</translation>
    </message>
    <message>
        <source>the contour program {1} has no formula QC.. = ...</source>
        <translation>o programa de contorno {1} não tem fórmula QC.. = ...</translation>
    </message>
    <message>
        <source>the contour program {1} has no contour</source>
        <translation>o programa de contorno {1} não tem contorno</translation>
    </message>
    <message>
        <source>the contour of {1} lies beyond 1,000,000 mm from the origin</source>
        <translation>o contorno de {1} está a mais de 1.000.000 mm da origem</translation>
    </message>
    <message>
        <source>the contour of {1} encloses no area</source>
        <translation>o contorno de {1} não encerra nenhuma área</translation>
    </message>
    <message>
        <source>the contour of {1} intersects itself</source>
        <translation>o contorno de {1} intersecta-se a si próprio</translation>
    </message>
    <message>
        <source>no input is asked for</source>
        <translation>nenhuma entrada é pedida</translation>
    </message>
    <message>
        <source>a customisation program runs in the user channel: it has no ISO blocks (no motion, no M, S, T)</source>
        <translation>um programa de personalização é executado no canal do usuário: não tem blocos ISO (sem movimento, sem M, S, T)</translation>
    </message>
    <message>
        <source>{1} is a screen customisation instruction: it runs only in a user customisation program (the user screen)</source>
        <translation>{1} é uma instrução de personalização da tela: só é executada num programa de personalização do usuário (a tela do usuário)</translation>
    </message>
    <message>
        <source>screen customisation instructions run only in a user customisation program (the user screen)</source>
        <translation>as instruções de personalização da tela só são executadas num programa de personalização do usuário (a tela do usuário)</translation>
    </message>
    <message>
        <source>data window {1} is not defined (ODW)</source>
        <translation>a janela de dados {1} não está definida (ODW)</translation>
    </message>
    <message>
        <source>WKEY: keys come from the PLC or DNC (KEYSRC), which this control does not have</source>
        <translation>WKEY: as teclas vêm do PLC ou do DNC (KEYSRC), que este comando não tem</translation>
    </message>
    <message>
        <source>WBUF runs only in the customisation program of the edit mode (USEREDIT)</source>
        <translation>WBUF só é executado no programa de personalização do modo de edição (USEREDIT)</translation>
    </message>
    <message>
        <source>{1}: inputs are IB0-IB25</source>
        <translation>{1}: as entradas são IB0-IB25</translation>
    </message>
    <message>
        <source>customisation instructions take global parameters, not the local P{1}</source>
        <translation>as instruções de personalização aceitam parâmetros globais, não o local P{1}</translation>
    </message>
    <message>
        <source>input format [-]i.d expected (i integer digits 0-6, d decimals 0-5)</source>
        <translation>esperado o formato de entrada [-]i.d (i dígitos inteiros 0-6, d decimais 0-5)</translation>
    </message>
    <message>
        <source>a softkey text has at most 20 characters</source>
        <translation>o texto de uma softkey tem no máximo 20 caracteres</translation>
    </message>
    <message>
        <source>only positive values are accepted here</source>
        <translation>aqui só são aceitos valores positivos</translation>
    </message>
    <message>
        <source>a number is expected</source>
        <translation>é esperado um número</translation>
    </message>
    <message>
        <source>the number does not fit the input format</source>
        <translation>o número não cabe no formato de entrada</translation>
    </message>
    <message>
        <source>Exact radius of the calibration ring or stud</source>
        <translation>Raio exato do anel ou da ilha de calibração</translation>
    </message>
    <message>
        <source>Number of touch points on the diameter (0: 4)</source>
        <translation>Número de pontos de apalpação no diâmetro (0: 4)</translation>
    </message>
    <message>
        <source>Reference angle: main axis to touch point 1</source>
        <translation>Ângulo de referência: eixo principal ao ponto de apalpação 1</translation>
    </message>
    <message>
        <source>Datum for the length: height of the ring&apos;s top face</source>
        <translation>Ponto de referência para o comprimento: altura da face superior do anel</translation>
    </message>
    <message>
        <source>CALIBRATE TS LENGTH</source>
        <translation>CALIBRAR COMPRIMENTO DE TS</translation>
    </message>
    <message>
        <source>CALIBRATE TS IN RING</source>
        <translation>CALIBRAR TS NO ANEL</translation>
    </message>
    <message>
        <source>CALIBRATE TS ON STUD</source>
        <translation>CALIBRAR TS NA ILHA</translation>
    </message>
    <message>
        <source>Measuring axis: 1 main axis, 2 secondary axis, 3 touch probe axis</source>
        <translation>Eixo de medição: 1 eixo principal, 2 eixo secundário, 3 eixo do apalpador</translation>
    </message>
    <message>
        <source>Axis for the compensation: 0 automatic, 4 A, 5 B, 6 C</source>
        <translation>Eixo para a compensação: 0 automático, 4 A, 5 B, 6 C</translation>
    </message>
    <message>
        <source>Set to zero after alignment: 0 no, 1 yes</source>
        <translation>Colocar a zero após o alinhamento: 0 não, 1 sim</translation>
    </message>
    <message>
        <source>Reference angle the probed line is aligned to</source>
        <translation>Ângulo de referência ao qual a reta apalpada é alinhada</translation>
    </message>
    <message>
        <source>cycle {1}: Q312 must be 0, 4, 5 or 6</source>
        <translation>ciclo {1}: Q312 tem de ser 0, 4, 5 ou 6</translation>
    </message>
    <message>
        <source>cycle {1}: the machine has no rotary table axis {2} to compensate the misalignment</source>
        <translation>ciclo {1}: a máquina não tem o eixo de mesa rotativa {2} para compensar o desalinhamento</translation>
    </message>
    <message>
        <source>cycle {1}: the rotary axis {2} cannot compensate a misalignment about the axis of {3}</source>
        <translation>ciclo {1}: o eixo rotativo {2} não pode compensar um desalinhamento em torno do eixo de {3}</translation>
    </message>
    <message>
        <source>Preset rotation angle: the basic rotation to set</source>
        <translation>Ângulo de rotação: a rotação básica a definir</translation>
    </message>
    <message>
        <source>Number in table: -1 the active preset, 0 preset 0 and active</source>
        <translation>Número na tabela: -1 o ponto de referência ativo, 0 o ponto 0 e ativo</translation>
    </message>
    <message>
        <source>Hole centre, main axis</source>
        <translation>Centro do furo, eixo principal</translation>
    </message>
    <message>
        <source>Hole centre, secondary axis: 0 aligns the hole to +Y</source>
        <translation>Centro do furo, eixo secundário: 0 alinha o furo com +Y</translation>
    </message>
    <message>
        <source>Nominal diameter (enter it on the small side)</source>
        <translation>Diâmetro nominal (introduzi-lo de preferência menor)</translation>
    </message>
    <message>
        <source>Set to zero after alignment: 0 the C display, n add to datum row n</source>
        <translation>Colocar a zero após o alinhamento: 0 a visualização de C, n somar à linha n de pontos zero</translation>
    </message>
    <message>
        <source>BASIC ROTATION COMPENSATED VIA ROTARY AXIS</source>
        <translation>ROTAÇÃO BÁSICA COMPENSADA POR EIXO ROTATIVO</translation>
    </message>
    <message>
        <source>SET BASIC ROTATION</source>
        <translation>DEFINIR ROTAÇÃO BÁSICA</translation>
    </message>
    <message>
        <source>ROT IN C AXIS</source>
        <translation>ROT MEDIANTE EIXO C</translation>
    </message>
    <message>
        <source>Positioning feed rate of the probe (FMAX: rapid traverse)</source>
        <translation>Avanço de posicionamento do apalpador (FMAX: marcha rápida)</translation>
    </message>
    <message>
        <source>Pre-position at machine rapid: 0 no (Q396), 1 yes</source>
        <translation>Pré-posicionar em marcha rápida da máquina: 0 não (Q396), 1 sim</translation>
    </message>
    <message>
        <source>Angle tracking: 0 no, 1 orient the probe before each touch</source>
        <translation>Seguimento angular: 0 não, 1 orientar o apalpador antes de cada apalpação</translation>
    </message>
    <message>
        <source>Automatic interruption: 0 never, 1 when a cycle shows its log</source>
        <translation>Interrupção automática: 0 nunca, 1 quando um ciclo mostra o seu protocolo</translation>
    </message>
    <message>
        <source>Nominal point, main axis</source>
        <translation>Ponto nominal, eixo principal</translation>
    </message>
    <message>
        <source>Nominal point, secondary axis</source>
        <translation>Ponto nominal, eixo secundário</translation>
    </message>
    <message>
        <source>Nominal point, tool axis</source>
        <translation>Ponto nominal, eixo da ferramenta</translation>
    </message>
    <message>
        <source>Surface normal, main axis component</source>
        <translation>Normal à superfície, componente do eixo principal</translation>
    </message>
    <message>
        <source>Surface normal, secondary axis component</source>
        <translation>Normal à superfície, componente do eixo secundário</translation>
    </message>
    <message>
        <source>Surface normal, tool axis component</source>
        <translation>Normal à superfície, componente do eixo da ferramenta</translation>
    </message>
    <message>
        <source>Tolerance along the normal, e.g. &quot;0.4-0.1&quot;</source>
        <translation>Tolerância ao longo da normal, p. ex. &quot;0.4-0.1&quot;</translation>
    </message>
    <message>
        <source>Tolerance error: 0 nothing, 1 stop, 2 stop on undersize only</source>
        <translation>Erro de tolerância: 0 nada, 1 paragem, 2 paragem só com submedida</translation>
    </message>
    <message>
        <source>cycle {1}: the surface normal Q581..Q583 is zero</source>
        <translation>ciclo {1}: a normal à superfície Q581..Q583 é nula</translation>
    </message>
    <message>
        <source>FAST PROBING</source>
        <translation>APALPAÇÃO RÁPIDA</translation>
    </message>
    <message>
        <source>PROBING IN 3-D</source>
        <translation>APALPAÇÃO 3D</translation>
    </message>
    <message>
        <source>Stop before running: 0 stop to position the tool, 1 no stop</source>
        <translation>Paragem antes de executar: 0 paragem para posicionar a ferramenta, 1 sem paragem</translation>
    </message>
    <message>
        <source>CALIBRATE IR TT</source>
        <translation>CALIBRAR TT IR</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: Q303 = 0 writes the active datum table: select one with SEL TABLE first</source>
        <translation>ciclo de apalpação {1}: Q303 = 0 escreve na tabela de pontos zero ativa: selecione uma antes com SEL TABLE</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the datum table: {2}</source>
        <translation>ciclo de apalpação {1}: não é possível escrever a tabela de pontos zero: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: calibration writes the probe&apos;s row of the tool table TOOL.T: call the probe from it</source>
        <translation>ciclo de apalpação {1}: a calibração escreve a linha do apalpador na tabela de ferramentas TOOL.T: chame o apalpador a partir dela</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the TT calibration: {2}</source>
        <translation>ciclo de apalpação {1}: não é possível escrever a calibração do TT: {2}</translation>
    </message>
    <message>
        <source>Cylinder radius</source>
        <translation>Raio do cilindro</translation>
    </message>
    <message>
        <source>Rotary-axis coordinates in the subprogram: 0 degrees, 1 mm/inch</source>
        <translation>Coordenadas do eixo rotativo no subprograma: 0 graus, 1 mm/polegada</translation>
    </message>
    <message>
        <source>Ridge width</source>
        <translation>Largura da nervura</translation>
    </message>
    <message>
        <source>Tolerance of the slot walls (0: no re-machining)</source>
        <translation>Tolerância das paredes da ranhura (0: sem pós-maquinagem)</translation>
    </message>
    <message>
        <source>cycle {1}: the cylinder radius Q16 must be greater than 0</source>
        <translation>ciclo {1}: o raio do cilindro Q16 tem de ser maior que 0</translation>
    </message>
    <message>
        <source>cycle {1}: program the contour subprogram with radius compensation RL or RR</source>
        <translation>ciclo {1}: programe o subprograma de contorno com correção de raio RL ou RR</translation>
    </message>
    <message>
        <source>cycle {1}: the centre line must be an open contour, not end where it starts</source>
        <translation>ciclo {1}: a linha central tem de ser um contorno aberto, não pode terminar onde começa</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE</source>
        <translation>SUPERFÍCIE CILÍNDRICA</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE SLOT</source>
        <translation>SUPERFÍCIE CILÍNDRICA RANHURA</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE RIDGE</source>
        <translation>SUPERFÍCIE CILÍNDRICA NERVURA</translation>
    </message>
    <message>
        <source>CYLINDER SURFACE CONTOUR</source>
        <translation>SUPERFÍCIE CILÍNDRICA CONTORNO</translation>
    </message>
    <message>
        <source>a thread cannot be cut on the development of a cylinder</source>
        <translation>não é possível cortar uma rosca no desenvolvimento de um cilindro</translation>
    </message>
    <message>
        <source>cycle {1} needs a rotary table described in the machine file ([kinematics], docs/machine-config.md)</source>
        <translation>o ciclo {1} precisa de uma mesa rotativa descrita no ficheiro da máquina ([kinematics], docs/machine-config.md)</translation>
    </message>
    <message>
        <source>cycle {1} cannot run with M128/FUNCTION TCPM active</source>
        <translation>o ciclo {1} não pode ser executado com M128/FUNCTION TCPM ativo</translation>
    </message>
    <message>
        <source>&apos;{1}&apos; is an output of this run and cannot be read</source>
        <translation>&apos;{1}&apos; é uma saída desta execução e não pode ser lido</translation>
    </message>
    <message>
        <source>TYPE OF DIMENSION</source>
        <translation>TIPO DE COTAGEM</translation>
    </message>
    <message>
        <source>RIDGE WIDTH</source>
        <translation>LARGURA NERVURA</translation>
    </message>
    <message>
        <source>the contour subprogram {1} has no contour</source>
        <translation>o subprograma de contorno {1} não tem contorno</translation>
    </message>
    <message>
        <source>Dwell time at the bottom</source>
        <translation>Tempo de espera no fundo</translation>
    </message>
    <message>
        <source>PECKING</source>
        <translation>FURAR EM PROFUNDIDADE</translation>
    </message>
    <message>
        <source>TAPPING</source>
        <translation>ROSCAGEM</translation>
    </message>
    <message>
        <source>Set-up clearance: tool tip at the start to surface</source>
        <translation>Distância de segurança: ponta da ferramenta no início até à superfície</translation>
    </message>
    <message>
        <source>Depth from the surface (the sign gives the direction)</source>
        <translation>Profundidade a partir da superfície (o sinal dá a direção)</translation>
    </message>
    <message>
        <source>Feed rate</source>
        <translation>Avanço</translation>
    </message>
    <message>
        <source>Feed rate for plunging (none: the milling feed)</source>
        <translation>Avanço de penetração (nenhum: o avanço de fresagem)</translation>
    </message>
    <message>
        <source>Direction: DR+ counterclockwise, DR- clockwise</source>
        <translation>Sentido: DR+ anti-horário, DR- horário</translation>
    </message>
    <message>
        <source>First side length (parallel to the first axis)</source>
        <translation>Comprimento do 1.º lado (paralelo ao primeiro eixo)</translation>
    </message>
    <message>
        <source>Pocket radius</source>
        <translation>Raio da caixa</translation>
    </message>
    <message>
        <source>cycle {1} has no sub-block {1}.{2}</source>
        <translation>o ciclo {1} não tem sub-bloco {1}.{2}</translation>
    </message>
    <message>
        <source>cycle {1}: the tool axis must be perpendicular to the axis of rotary table {2} (tilt the table or the head first, e.g. with PLANE)</source>
        <translation>ciclo {1}: o eixo da ferramenta deve ser perpendicular ao eixo da mesa rotativa {2} (incline primeiro a mesa ou a cabeça, p. ex. com PLANE)</translation>
    </message>
    <message>
        <source>PLANE AXIAL: {1} is not a rotary axis of the kinematics of this machine</source>
        <translation>PLANE AXIAL: {1} não é um eixo rotativo da cinemática desta máquina</translation>
    </message>
    <message>
        <source>TCPM needs the rotary axes described in the machine file ([kinematics], e.g. --machine mill5)</source>
        <translation>TCPM precisa dos eixos rotativos descritos no ficheiro da máquina ([kinematics], p. ex. --machine mill5)</translation>
    </message>
    <message>
        <source>How the rotary axes are built: none, one rotary table, a table on a tilting table, a swivel head and a table, or a fork head</source>
        <translation>Como os eixos rotativos são construídos: nenhum, uma mesa rotativa, uma mesa sobre uma mesa basculante, uma cabeça basculante e uma mesa, ou uma cabeça de garfo</translation>
    </message>
    <message>
        <source>The tilting rotary axis (SEQ+/SEQ- choose its sign)</source>
        <translation>O eixo rotativo basculante (SEQ+/SEQ- escolhem o seu sinal)</translation>
    </message>
    <message>
        <source>The second rotary axis: the table on the tilting table, the table of a head-table machine, the head axis carrying the fork</source>
        <translation>O segundo eixo rotativo: a mesa sobre a mesa basculante, a mesa de uma máquina cabeça-mesa, o eixo da cabeça que leva o garfo</translation>
    </message>
    <message>
        <source>Head: X of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Cabeça: X do pivô da cabeça a partir do nariz do mandril, cabeça em 0; escreva head_pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Head: Y of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Cabeça: Y do pivô da cabeça a partir do nariz do mandril, cabeça em 0; escreva head_pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>Head: Z of the head&apos;s pivot from the spindle nose, head at 0; write head_pivot = [x, y, z]</source>
        <translation>Cabeça: Z do pivô da cabeça a partir do nariz do mandril, cabeça em 0; escreva head_pivot = [x, y, z]</translation>
    </message>
    <message>
        <source>kinematics.primary is the tilting axis: A or B, not C</source>
        <translation>kinematics.primary é o eixo basculante: A ou B, não C</translation>
    </message>
    <message>
        <source>FK: {1} is not an axis of the working plane</source>
        <translation>FK: {1} não é um eixo do plano de maquinagem</translation>
    </message>
    <message>
        <source>G53 in a profile needs a G00 or G01 point in X, Z</source>
        <translation>G53 num perfil precisa de um ponto G00 ou G01 em X, Z</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: it rises {3}° from the passes and the cutting angle CUTA allows {4}°</source>
        <translation>a ferramenta T{1} não alcança o perfil na linha {2}: sobe {3}° em relação às passadas e o ângulo de corte CUTA permite {4}°</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: it descends {3}° into the material and CUTA + NOSEA leave {4}°</source>
        <translation>a ferramenta T{1} não alcança o perfil na linha {2}: desce {3}° para o material e CUTA + NOSEA deixam {4}°</translation>
    </message>
    <message>
        <source>Exact radius of the calibration sphere</source>
        <translation>Raio exato da esfera de calibração</translation>
    </message>
    <message>
        <source>Calibrate the length too: 0 no, 1 yes</source>
        <translation>Calibrar também o comprimento: 0 não, 1 sim</translation>
    </message>
    <message>
        <source>Datum for the length: height of the sphere&apos;s centre</source>
        <translation>Ponto de referência do comprimento: altura do centro da esfera</translation>
    </message>
    <message>
        <source>Number of points for the 3D calibration (0: none)</source>
        <translation>Número de pontos para a calibração 3D (0: nenhuma)</translation>
    </message>
    <message>
        <source>cycle {1}: the 3D calibration (Q455 &gt; 0, option 92) is not available; set Q455 = 0</source>
        <translation>ciclo {1}: a calibração 3D (Q455 &gt; 0, opção 92) não está disponível; defina Q455 = 0</translation>
    </message>
    <message>
        <source>CALIBRATE TS ON SPHERE</source>
        <translation>CALIBRAR TS NA ESFERA</translation>
    </message>
    <message>
        <source>Result parameter</source>
        <translation>Parâmetro de resultado</translation>
    </message>
    <message>
        <source>Probing angle</source>
        <translation>Ângulo de apalpação</translation>
    </message>
    <message>
        <source>Maximum measuring path</source>
        <translation>Percurso de medição máximo</translation>
    </message>
    <message>
        <source>Measuring feed</source>
        <translation>Avanço de medição</translation>
    </message>
    <message>
        <source>Maximum retraction path</source>
        <translation>Percurso de retrocesso máximo</translation>
    </message>
    <message>
        <source>Reference system: 0 active, 1 machine</source>
        <translation>Sistema de referência: 0 ativo, 1 máquina</translation>
    </message>
    <message>
        <source>Error mode: 0 error if deflected at the start, 1 status -1</source>
        <translation>Modo de erro: 0 erro se defletido no início, 1 estado -1</translation>
    </message>
    <message>
        <source>{1}.{2}: the probing axis X, Y or Z expected</source>
        <translation>{1}.{2}: esperado o eixo de apalpação X, Y ou Z</translation>
    </message>
    <message>
        <source>{1}.{2}: the probing direction IX, IY, IZ is zero</source>
        <translation>{1}.{2}: a direção de apalpação IX, IY, IZ é nula</translation>
    </message>
    <message>
        <source>G55: the probing axis with its direction (X-, Y+ ...) expected</source>
        <translation>G55: esperado o eixo de apalpação com a sua direção (X-, Y+ ...)</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): X of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Esfera de calibração (ciclo 460): X do seu centro no referencial programado do bloco; escreva centre = [x, y, z]</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): Y of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Esfera de calibração (ciclo 460): Y do seu centro no referencial programado do bloco; escreva centre = [x, y, z]</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): Z of its centre in the blank&apos;s programmed frame; write centre = [x, y, z]</source>
        <translation>Esfera de calibração (ciclo 460): Z do seu centro no referencial programado do bloco; escreva centre = [x, y, z]</translation>
    </message>
    <message>
        <source>Calibration sphere (cycle 460): its exact radius; 0: none</source>
        <translation>Esfera de calibração (ciclo 460): o seu raio exato; 0: nenhuma</translation>
    </message>
    <message>
        <source>tool T{1} cannot reach the profile at line {2}: the arc&apos;s radius {3} is smaller than the nose radius {4}</source>
        <translation>a ferramenta T{1} não alcança o perfil na linha {2}: o raio do arco {3} é menor que o raio da ponta {4}</translation>
    </message>
    <message>
        <source>a label number from 1 to 65535 or a name expected</source>
        <translation>esperava-se um número de label de 1 a 65535 ou um nome</translation>
    </message>
    <message>
        <source>cycle {1}: {2} expected in {1}.{3}</source>
        <translation>ciclo {1}: esperado {2} em {1}.{3}</translation>
    </message>
    <message>
        <source>FUNCTION MODE MILL: the machine file sets the kinematics; &apos;{1}&apos; cannot be selected</source>
        <translation>FUNCTION MODE MILL: a cinemática é fixada pelo ficheiro da máquina; &apos;{1}&apos; não pode ser selecionada</translation>
    </message>
    <message>
        <source>FUNCTION MODE TURN: this machine has no turning mode</source>
        <translation>FUNCTION MODE TURN: esta máquina não tem modo de torneamento</translation>
    </message>
    <message>
        <source>FUNCTION MODE: MILL or TURN expected</source>
        <translation>FUNCTION MODE: esperado MILL ou TURN</translation>
    </message>
    <message>
        <source>M120 LA: a whole number of blocks from 0 to 99</source>
        <translation>M120 LA: um número inteiro de blocos de 0 a 99</translation>
    </message>
    <message>
        <source>CALL SELECTED PGM: no program was selected with SEL PGM</source>
        <translation>CALL SELECTED PGM: nenhum programa foi selecionado com SEL PGM</translation>
    </message>
    <message>
        <source>cycle {1}: no room for the helical plunge, and the reciprocating plunge needs the tool&apos;s LCUTS (pre-drill with cycle 21 or use a centre-cutting tool)</source>
        <translation>ciclo {1}: não há espaço para a penetração helicoidal, e a penetração pendular precisa do LCUTS da ferramenta (pré-furar com o ciclo 21 ou usar uma ferramenta de corte ao centro)</translation>
    </message>
    <message>
        <source>Axis of the first side length: 0 main axis, 1 secondary axis</source>
        <translation>Eixo do primeiro comprimento lateral: 0 eixo principal, 1 eixo secundário</translation>
    </message>
    <message>
        <source>cycle {1}: the tool diameter must be at least half the slot width</source>
        <translation>ciclo {1}: o diâmetro da ferramenta deve ser pelo menos metade da largura da ranhura</translation>
    </message>
    <message>
        <source>cycle {1}: the slot is shorter than it is wide</source>
        <translation>ciclo {1}: a ranhura é mais curta do que larga</translation>
    </message>
    <message>
        <source>manual probing: call the touch probe with TOOL CALL first (MDI)</source>
        <translation>apalpação manual: chame primeiro o apalpador com TOOL CALL (MDI)</translation>
    </message>
    <message>
        <source>manual probing: tool {1} is not in TOOL.T</source>
        <translation>apalpação manual: a ferramenta {1} não está em TOOL.T</translation>
    </message>
    <message>
        <source>manual probing: probe {1} is not in tchprobe.tp</source>
        <translation>apalpação manual: o apalpador {1} não está em tchprobe.tp</translation>
    </message>
    <message>
        <source>In ISO programs cycle %1 takes only %2: leave the other fields empty</source>
        <translation>Em programas ISO o ciclo %1 aceita apenas %2: deixe os outros campos vazios</translation>
    </message>
    <message>
        <source>the rotary axes turn too far in this block to keep the tool tip on the path; split the block</source>
        <translation>os eixos rotativos giram demais neste bloco para manter a ponta da ferramenta na trajetória; divida o bloco</translation>
    </message>
    <message>
        <source>M94 {1}: the machine has no rotary axis {1}</source>
        <translation>M94 {1}: a máquina não tem eixo rotativo {1}</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest X, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Bloco bruto simulado de um programa sem BLK FORM: o seu X mínimo, coordenadas da peça do preset do ficheiro da máquina; escreva min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest Y, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Bloco bruto simulado de um programa sem BLK FORM: o seu Y mínimo, coordenadas da peça do preset do ficheiro da máquina; escreva min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its lowest Z, workpiece coordinates of the machine file&apos;s preset; write min = [x, y, z]</source>
        <translation>Bloco bruto simulado de um programa sem BLK FORM: o seu Z mínimo, coordenadas da peça do preset do ficheiro da máquina; escreva min = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest X, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Bloco bruto simulado de um programa sem BLK FORM: o seu X máximo, coordenadas da peça do preset do ficheiro da máquina; escreva max = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest Y, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Bloco bruto simulado de um programa sem BLK FORM: o seu Y máximo, coordenadas da peça do preset do ficheiro da máquina; escreva max = [x, y, z]</translation>
    </message>
    <message>
        <source>Simulated blank of a program without BLK FORM: its highest Z, workpiece coordinates of the machine file&apos;s preset; write max = [x, y, z]</source>
        <translation>Bloco bruto simulado de um programa sem BLK FORM: o seu Z máximo, coordenadas da peça do preset do ficheiro da máquina; escreva max = [x, y, z]</translation>
    </message>
    <message>
        <source>tool length touch-off: no tool in the spindle</source>
        <translation>Medição do comprimento por toque: nenhuma ferramenta no mandril</translation>
    </message>
    <message>
        <source>tool length touch-off: tool {1} is not in TOOL.T</source>
        <translation>Medição do comprimento por toque: a ferramenta {1} não está em TOOL.T</translation>
    </message>
    <message>
        <source>Positioning: TURN, MOVE (DIST) or STAY</source>
        <translation>Posicionamento: TURN, MOVE (DIST) ou STAY</translation>
    </message>
    <message>
        <source>Retract along the tool axis first: MAX or mm</source>
        <translation>Retirar primeiro no eixo da ferramenta: MAX ou mm</translation>
    </message>
    <message>
        <source>MOVE: distance of the tool tip from the centre of rotation</source>
        <translation>MOVE: distância da ponta da ferramenta ao centro de rotação</translation>
    </message>
    <message>
        <source>Feed rate of the positioning, or FMAX</source>
        <translation>Avanço do posicionamento ou FMAX</translation>
    </message>
    <message>
        <source>Solution: SEQ+ or SEQ- (empty: the machine&apos;s)</source>
        <translation>Solução: SEQ+ ou SEQ- (vazio: a da máquina)</translation>
    </message>
    <message>
        <source>Transformation: COORD ROT or TABLE ROT</source>
        <translation>Transformação: COORD ROT ou TABLE ROT</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not allowed here</source>
        <translation>%1: «%2» não é permitido aqui</translation>
    </message>
    <message>
        <source>Spatial angle A [°]</source>
        <translation>Ângulo espacial A [°]</translation>
    </message>
    <message>
        <source>Spatial angle B [°]</source>
        <translation>Ângulo espacial B [°]</translation>
    </message>
    <message>
        <source>Spatial angle C [°]</source>
        <translation>Ângulo espacial C [°]</translation>
    </message>
    <message>
        <source>Projected angle in the principal plane [°]</source>
        <translation>Ângulo de projeção no plano principal [°]</translation>
    </message>
    <message>
        <source>Projected angle in the minor plane [°]</source>
        <translation>Ângulo de projeção no plano secundário [°]</translation>
    </message>
    <message>
        <source>Rotation in the tilted plane [°]</source>
        <translation>Rotação no plano inclinado [°]</translation>
    </message>
    <message>
        <source>Precession angle [°]</source>
        <translation>Ângulo de precessão [°]</translation>
    </message>
    <message>
        <source>Nutation angle [°]</source>
        <translation>Ângulo de nutação [°]</translation>
    </message>
    <message>
        <source>Rotation angle [°]</source>
        <translation>Ângulo de rotação [°]</translation>
    </message>
    <message>
        <source>Base vector (X direction)</source>
        <translation>Vetor base (direção X)</translation>
    </message>
    <message>
        <source>Normal vector</source>
        <translation>Vetor normal</translation>
    </message>
    <message>
        <source>First point (origin of X)</source>
        <translation>Primeiro ponto (origem de X)</translation>
    </message>
    <message>
        <source>Second point (on the X axis)</source>
        <translation>Segundo ponto (no eixo X)</translation>
    </message>
    <message>
        <source>Third point (in the plane)</source>
        <translation>Terceiro ponto (no plano)</translation>
    </message>
    <message>
        <source>Axis of the incremental spatial angle</source>
        <translation>Eixo do ângulo espacial incremental</translation>
    </message>
    <message>
        <source>Incremental angle [°]</source>
        <translation>Ângulo incremental [°]</translation>
    </message>
    <message>
        <source>Axis angle [°] (empty: not moved)</source>
        <translation>Ângulo do eixo [°] (vazio: não se move)</translation>
    </message>
    <message>
        <source>Feed rate at the tool tip</source>
        <translation>Avanço na ponta da ferramenta</translation>
    </message>
    <message>
        <source>Rotary axes: machine positions</source>
        <translation>Eixos rotativos: posições da máquina</translation>
    </message>
    <message>
        <source>Path: the axes interpolate linearly</source>
        <translation>Trajetória: os eixos interpolam linearmente</translation>
    </message>
    <message>
        <source>Reference point: the tool tip</source>
        <translation>Ponto de referência: a ponta da ferramenta</translation>
    </message>
    <message>
        <source>Feed rate of the compensating moves</source>
        <translation>Avanço dos movimentos de compensação</translation>
    </message>
    <message>
        <source>Program name, e.g. PART or TNC:\DIR\PART.H</source>
        <translation>Nome do programa, p. ex. PART ou TNC:\DIR\PART.H</translation>
    </message>
    <message>
        <source>PLANE AXIAL: enter the angle of A, B or C</source>
        <translation>PLANE AXIAL: introduzir o ângulo de A, B ou C</translation>
    </message>
    <message>
        <source>STAY moves nothing: leave MB, DIST and F empty</source>
        <translation>STAY não move nada: deixar MB, DIST e F vazios</translation>
    </message>
    <message>
        <source>DIST belongs to MOVE</source>
        <translation>DIST pertence a MOVE</translation>
    </message>
    <message>
        <source>stopped after {1} blocks: endless loop? (--max-blocks)</source>
        <translation>parado após {1} blocos: ciclo infinito? (--max-blocks)</translation>
    </message>
    <message>
        <source>LN needs all of NX NY NZ, and TX TY TZ all or none</source>
        <translation>LN precisa de NX NY NZ completos, e TX TY TZ todos ou nenhum</translation>
    </message>
    <message>
        <source>FUNCTION TCPM: only F TCP|CONT, AXIS POS|SPAT, PATHCTRL AXIS|VECTOR and REFPNT TIP-TIP are supported, not &apos;{1}&apos;</source>
        <translation>FUNCTION TCPM: só são suportados F TCP|CONT, AXIS POS|SPAT, PATHCTRL AXIS|VECTOR e REFPNT TIP-TIP, não &apos;{1}&apos;</translation>
    </message>
    <message>
        <source>LN compensates along the surface normal: switch the radius compensation off (R0) first</source>
        <translation>LN corrige ao longo da normal à superfície: desligue primeiro a correção do raio (R0)</translation>
    </message>
    <message>
        <source>LN: a vector NX NY NZ or TX TY TZ has no length</source>
        <translation>LN: um vetor NX NY NZ ou TX TY TZ não tem comprimento</translation>
    </message>
    <message>
        <source>LN: the rotary axes of this machine cannot turn the tool along TX TY TZ</source>
        <translation>LN: os eixos rotativos desta máquina não conseguem rodar a ferramenta segundo TX TY TZ</translation>
    </message>
    <message>
        <source>with TCPM on the program positions the rotary axes: tilt with STAY, or switch TCPM off first</source>
        <translation>com TCPM ativo o programa posiciona os eixos rotativos: incline com STAY ou desligue primeiro o TCPM</translation>
    </message>
    <message>
        <source>AXIS SPAT: the rotary axes of this machine cannot turn the tool to the spatial angles A {1} B {2} C {3}</source>
        <translation>AXIS SPAT: os eixos rotativos desta máquina não conseguem rodar a ferramenta para os ângulos espaciais A {1} B {2} C {3}</translation>
    </message>
    <message>
        <source>the arc&apos;s radius {1} is smaller than the tool nose radius {2}: the nose cannot follow it</source>
        <translation>o raio do arco {1} é menor que o raio da ponta {2} da ferramenta: a ponta não o pode seguir</translation>
    </message>
    <message>
        <source>Pattern repeat cycle</source>
        <translation>Ciclo fixo de seguimento de perfil</translation>
    </message>
    <message>
        <source>Stock removal cycle along X</source>
        <translation>Ciclo fixo de desbaste no eixo X</translation>
    </message>
    <message>
        <source>Stock removal cycle along Z</source>
        <translation>Ciclo fixo de desbaste no eixo Z</translation>
    </message>
    <message>
        <source>Turning cycle, straight sections</source>
        <translation>Ciclo fixo de torneamento de trechos retos</translation>
    </message>
    <message>
        <source>Facing cycle, straight sections</source>
        <translation>Ciclo fixo de faceamento de trechos retos</translation>
    </message>
    <message>
        <source>Axial drilling / tapping cycle</source>
        <translation>Ciclo fixo de perfuração axial / rosqueamento com macho</translation>
    </message>
    <message>
        <source>Turning cycle, curved sections</source>
        <translation>Ciclo fixo de torneamento de trechos curvos</translation>
    </message>
    <message>
        <source>Facing cycle, curved sections</source>
        <translation>Ciclo fixo de faceamento de trechos curvos</translation>
    </message>
    <message>
        <source>Longitudinal threading cycle</source>
        <translation>Ciclo fixo de rosqueamento longitudinal</translation>
    </message>
    <message>
        <source>Face threading cycle</source>
        <translation>Ciclo fixo de rosqueamento frontal</translation>
    </message>
    <message>
        <source>Grooving cycle along X</source>
        <translation>Ciclo fixo de ranhura no eixo X</translation>
    </message>
    <message>
        <source>the program check stopped after {1} blocks: endless loop?</source>
        <translation>a verificação do programa parou após {1} blocos: ciclo infinito?</translation>
    </message>
    <message>
        <source>Grooving cycle along Z</source>
        <translation>Ciclo fixo de ranhura no eixo Z</translation>
    </message>
    <message>
        <source>tapping and thread cutting follow the spindle along the tool axis: switch TCPM off first (M129 or FUNCTION RESET TCPM)</source>
        <translation>a roscagem com macho e o corte de rosca seguem a árvore ao longo do eixo da ferramenta: desligue primeiro o TCPM (M129 ou FUNCTION RESET TCPM)</translation>
    </message>
    <message>
        <source>cannot write the calibration log {1}: {2}</source>
        <translation>não é possível escrever o protocolo de calibração {1}: {2}</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the touch-probe table: {2}</source>
        <translation>ciclo de apalpação {1}: não é possível escrever a tabela de apalpadores: {2}</translation>
    </message>
    <message>
        <source>{1} must be an array of two numbers [x, y] within +-10 mm, not {2}</source>
        <translation>{1} deve ser uma lista de dois números [x, y] dentro de +-10 mm, não {2}</translation>
    </message>
    <message>
        <source>probe {1} is not in the touch-probe table</source>
        <translation>o apalpador {1} não está na tabela de apalpadores</translation>
    </message>
    <message>
        <source>cannot add a column &quot;{1}&quot;</source>
        <translation>não é possível adicionar a coluna &quot;{1}&quot;</translation>
    </message>
    <message>
        <source>{1} is not allowed beside the polar coordinates PR/PA (only the tool axis may be programmed)</source>
        <translation>{1} não é permitido junto às coordenadas polares PR/PA (só o eixo da ferramenta pode ser programado)</translation>
    </message>
    <message>
        <source>QR{1} = &apos;{2}&apos; is not a finite number</source>
        <translation>QR{1} = &apos;{2}&apos; não é um número finito</translation>
    </message>
    <message>
        <source>column {1} needs a whole number from 0 to {2}, not &quot;{3}&quot;</source>
        <translation>a coluna {1} precisa de um número inteiro de 0 a {2}, não &quot;{3}&quot;</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: the probe {2} cannot be turned to each probing direction (angle tracking of cycle 441, Q399 = 1)</source>
        <translation>ciclo de apalpação {1}: o apalpador {2} não pode ser orientado para cada direção de apalpação (seguimento angular do ciclo 441, Q399 = 1)</translation>
    </message>
    <message>
        <source>column TYPE: unknown probe &quot;{1}&quot; (known: {2})</source>
        <translation>coluna TYPE: apalpador desconhecido &quot;{1}&quot; (conhecidos: {2})</translation>
    </message>
    <message>
        <source>TRACK ON needs a probe the spindle can turn to any angle; {1} cannot be</source>
        <translation>TRACK ON precisa de um apalpador que a árvore possa orientar em qualquer ângulo; {1} não pode</translation>
    </message>
    <message>
        <source>LN: the tool is larger than the CAM system&apos;s (DR {1}, DR2 {2} from the tool table and TOOL CALL): program M107 to permit positive oversizes</source>
        <translation>LN: a ferramenta é maior do que a do sistema CAM (DR {1}, DR2 {2} da tabela de ferramentas e TOOL CALL): programe M107 para permitir sobremedidas positivas</translation>
    </message>
    <message>
        <source>LN: the corner radius R2+DR2 {1} must lie between 0 (end mill) and the radius R+DR {2} (ball cutter)</source>
        <translation>LN: o raio de canto R2+DR2 {1} deve estar entre 0 (fresa de topo) e o raio R+DR {2} (fresa esférica)</translation>
    </message>
    <message>
        <source>LN: the rotary axes of this machine cannot turn the tool along the surface normal NX NY NZ</source>
        <translation>LN: os eixos rotativos desta máquina não conseguem orientar a ferramenta segundo a normal de superfície NX NY NZ</translation>
    </message>
    <message>
        <source>LN is the conversational straight line with 3D tool compensation; in ISO write G01 X Y Z NX NY NZ [TX TY TZ]</source>
        <translation>LN é a reta em diálogo conversacional com correção 3D da ferramenta; em ISO escreva G01 X Y Z NX NY NZ [TX TY TZ]</translation>
    </message>
    <message>
        <source>surface vectors NX NY NZ TX TY TZ belong to a straight line G00/G01</source>
        <translation>os vetores de superfície NX NY NZ TX TY TZ pertencem a uma reta G00/G01</translation>
    </message>
    <message>
        <source>SL cycles (21-25, 275, 276) end back at the position before the cycle (the TNC&apos;s posAfterContPocket = PosBeforeMachining); false: at the clearance height Q7, the tool axis only (ToolAxClearanceHeight)</source>
        <translation>Os ciclos SL (21-25, 275, 276) terminam de novo na posição anterior ao ciclo (posAfterContPocket = PosBeforeMachining do TNC); false: na altura segura Q7, apenas no eixo da ferramenta (ToolAxClearanceHeight)</translation>
    </message>
    <message>
        <source>the simulated part holds the cuts of the first {1} tool moves only: later moves removed no material</source>
        <translation>a peça simulada contém apenas os cortes dos primeiros {1} movimentos da ferramenta: os movimentos seguintes não removeram material</translation>
    </message>
    <message>
        <source>Allowance in the 1st axis left by roughing</source>
        <translation>Sobremetal no 1.º eixo deixado pelo desbaste</translation>
    </message>
    <message>
        <source>POCKET FINISHING</source>
        <translation>ACABAMENTO DE CAIXA</translation>
    </message>
    <message>
        <source>STUD FINISHING</source>
        <translation>ACABAMENTO DE ILHA</translation>
    </message>
    <message>
        <source>CIRCULAR POCKET FINISHING</source>
        <translation>ACABAMENTO DE CAIXA CIRCULAR</translation>
    </message>
    <message>
        <source>CIRCULAR STUD FINISHING</source>
        <translation>ACABAMENTO DE ILHA CIRCULAR</translation>
    </message>
    <message>
        <source>Number of cuts</source>
        <translation>Número de cortes</translation>
    </message>
    <message>
        <source>Feed rate to the starting point in the tool axis</source>
        <translation>Avanço até ao ponto inicial no eixo da ferramenta</translation>
    </message>
    <message>
        <source>Feed rate for stepover (FMAX: rapid)</source>
        <translation>Avanço para o deslocamento lateral (FMAX: rápido)</translation>
    </message>
    <message>
        <source>MULTIPASS MILLING</source>
        <translation>FRESAGEM EM VÁRIAS PASSAGENS</translation>
    </message>
    <message>
        <source>SLOT RECIP. PLNG.</source>
        <translation>RANHURA PENDULAR</translation>
    </message>
    <message>
        <source>Starting point in the 3rd axis</source>
        <translation>Ponto inicial no 3.º eixo</translation>
    </message>
    <message>
        <source>2nd point in the 1st axis</source>
        <translation>2.º ponto no 1.º eixo</translation>
    </message>
    <message>
        <source>2nd point in the 2nd axis</source>
        <translation>2.º ponto no 2.º eixo</translation>
    </message>
    <message>
        <source>2nd point in the 3rd axis</source>
        <translation>2.º ponto no 3.º eixo</translation>
    </message>
    <message>
        <source>3rd point in the 1st axis</source>
        <translation>3.º ponto no 1.º eixo</translation>
    </message>
    <message>
        <source>3rd point in the 2nd axis</source>
        <translation>3.º ponto no 2.º eixo</translation>
    </message>
    <message>
        <source>3rd point in the 3rd axis</source>
        <translation>3.º ponto no 3.º eixo</translation>
    </message>
    <message>
        <source>4th point in the 1st axis</source>
        <translation>4.º ponto no 1.º eixo</translation>
    </message>
    <message>
        <source>4th point in the 2nd axis</source>
        <translation>4.º ponto no 2.º eixo</translation>
    </message>
    <message>
        <source>4th point in the 3rd axis</source>
        <translation>4.º ponto no 3.º eixo</translation>
    </message>
    <message>
        <source>RULED SURFACE</source>
        <translation>SUPERFÍCIE REGRADA</translation>
    </message>
    <message>
        <source>cycle {1}: the two points of a measured line coincide</source>
        <translation>ciclo {1}: os dois pontos de uma reta medida coincidem</translation>
    </message>
    <message>
        <source>mm (radius)</source>
        <translation>mm (raio)</translation>
    </message>
    <message>
        <source>collision: a rapid move runs into the material of the blank</source>
        <translation>colisão: um movimento em marcha rápida entra no material do bloco</translation>
    </message>
    <message>
        <source>ready</source>
        <comment>machine state</comment>
        <translation>pronta</translation>
    </message>
    <message>
        <source>running</source>
        <comment>machine state</comment>
        <translation>em execução</translation>
    </message>
    <message>
        <source>feed hold</source>
        <comment>machine state</comment>
        <translation>paragem do avanço</translation>
    </message>
    <message>
        <source>stopped</source>
        <comment>machine state</comment>
        <translation>parada</translation>
    </message>
    <message>
        <source>jogging</source>
        <comment>machine state</comment>
        <translation>em deslocação manual</translation>
    </message>
    <message>
        <source>homing</source>
        <comment>machine state</comment>
        <translation>a referenciar</translation>
    </message>
    <message>
        <source>stopping</source>
        <comment>machine state</comment>
        <translation>a parar</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <comment>machine state</comment>
        <translation>paragem de emergência</translation>
    </message>
    <message>
        <source>fault</source>
        <comment>machine state</comment>
        <translation>avaria</translation>
    </message>
    <message>
        <source>no machine</source>
        <comment>machine state</comment>
        <translation>sem máquina</translation>
    </message>
    <message>
        <source>Block {1}: the machine has no axis {2}.</source>
        <translation>Bloco {1}: a máquina não tem eixo {2}.</translation>
    </message>
    <message>
        <source>Block {1}: the move would take axis {2} to {3} (machine coordinates), beyond its soft limit {4}; the program is not run past this block.</source>
        <translation>Bloco {1}: o movimento levaria o eixo {2} a {3} (coordenadas da máquina), além do seu limite de software {4}; o programa não é executado para além deste bloco.</translation>
    </message>
    <message>
        <source>Block {1}: feed per revolution with the spindle stopped.</source>
        <translation>Bloco {1}: avanço por rotação com o mandril parado.</translation>
    </message>
    <message>
        <source>Block {1}: feed move without a feed rate.</source>
        <translation>Bloco {1}: movimento de avanço sem velocidade de avanço.</translation>
    </message>
    <message>
        <source>Block {1}: {2} = {3} is outside the range of the control; the program is not run past this block.</source>
        <translation>Bloco {1}: {2} = {3} está fora da gama do comando; o programa não é executado para além deste bloco.</translation>
    </message>
    <message>
        <source>Block {1}: the arc&apos;s end point is {2} mm off its circle.</source>
        <translation>Bloco {1}: o ponto final do arco fica a {2} mm do seu círculo.</translation>
    </message>
    <message>
        <source>Block {1}: threads with a variable lead (G34) cannot be executed yet.</source>
        <translation>Bloco {1}: as roscas de passo variável (G34) ainda não podem ser executadas.</translation>
    </message>
    <message>
        <source>Block {1}: spindle-synchronised move without a lead or a spindle speed.</source>
        <translation>Bloco {1}: movimento sincronizado com o mandril sem passo nem velocidade do mandril.</translation>
    </message>
    <message>
        <source>Cannot write the samples file {1}.</source>
        <translation>Não é possível escrever o ficheiro de amostras {1}.</translation>
    </message>
    <message>
        <source>Motion error {1} at line {2}.</source>
        <translation>Erro de movimento {1} na linha {2}.</translation>
    </message>
    <message>
        <source>Emergency stop at {1} s after the start (the button was pressed): every axis and the spindle were stopped and the program was aborted.</source>
        <translation>Paragem de emergência {1} s após o início (o botão foi premido): todos os eixos e o mandril foram parados e o programa foi interrompido.</translation>
    </message>
    <message>
        <source>The simulation reached its limit of {1} s of simulated time before the program&apos;s motion ended: the run stops here.</source>
        <translation>A simulação atingiu o seu limite de {1} s de tempo simulado antes de o movimento do programa terminar: a execução termina aqui.</translation>
    </message>
    <message>
        <source>cycle {1}: a rotation measured in the ZX or YZ plane (Q1139 = {2}) turns about X or Y; only a basic rotation about the tool axis can be accepted (Q1121 = 0)</source>
        <translation>ciclo {1}: uma rotação medida no plano ZX ou YZ (Q1139 = {2}) gira em torno de X ou Y; só se pode aceitar uma rotação básica em torno do eixo da ferramenta (Q1121 = 0)</translation>
    </message>
    <message>
        <source>cycle {1}: Q{2} is given as an actual position, but neither edge is probed along that axis</source>
        <translation>ciclo {1}: Q{2} foi indicado como posição real, mas nenhuma das arestas é apalpada ao longo desse eixo</translation>
    </message>
    <message>
        <source>Direction of the extrusion: 1 main axis, 2 secondary, 3 tool axis</source>
        <translation>Direção da extrusão: 1 eixo principal, 2 eixo secundário, 3 eixo da ferramenta</translation>
    </message>
    <message>
        <source>Length of the extrusion (incremental, the sign gives the way)</source>
        <translation>Comprimento da extrusão (incremental, o sinal indica o sentido)</translation>
    </message>
    <message>
        <source>Number of further touch points along the extrusion</source>
        <translation>Número de pontos de apalpação adicionais ao longo da extrusão</translation>
    </message>
    <message>
        <source>Extrusion active for: 0 the next 14xx cycle, 1 all following</source>
        <translation>Extrusão ativa para: 0 o ciclo 14xx seguinte, 1 todos os seguintes</translation>
    </message>
    <message>
        <source>PROBING EXTRUSION</source>
        <translation>APALPAR EXTRUSÃO</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) takes no actual position (nominal@actual is for the nominal positions of a 14xx cycle)</source>
        <translation>{1}: o parâmetro {2} ({3}) não aceita posição real (nominal@real é para as posições nominais de um ciclo 14xx)</translation>
    </message>
    <message>
        <source>the probe stopped {1} mm beyond its touch point, more than its stylus can be deflected ({2} mm): lower the probing feed F in tchprobe.tp</source>
        <translation>o apalpador parou {1} mm além do seu ponto de apalpação, mais do que a sua haste pode ser defletida ({2} mm): reduza o avanço de apalpação F em tchprobe.tp</translation>
    </message>
    <message>
        <source>touch probe cycle {1}: cannot write the simulated tools: {2}</source>
        <translation>ciclo de apalpação {1}: não é possível escrever as ferramentas simuladas: {2}</translation>
    </message>
    <message>
        <source>cycle 1416 (semi-automatic mode): position the probe before touch point {1} of edge {2}, within {3} mm of the edge, probing at {4} degrees in the plane; then NC start</source>
        <translation>ciclo 1416 (modo semiautomático): posicione o apalpador antes do ponto de apalpação {1} da aresta {2}, a no máximo {3} mm da aresta, apalpando a {4} graus no plano; depois Início NC</translation>
    </message>
    <message>
        <source>cycle {1}: the semi-automatic mode (&apos;?&apos;) cannot repeat its touches along an extrusion (cycle 1493)</source>
        <translation>ciclo {1}: o modo semiautomático (&apos;?&apos;) não pode repetir as apalpações ao longo de uma extrusão (ciclo 1493)</translation>
    </message>
    <message>
        <source>{1}: parameter {2} ({3}) cannot be unknown (&apos;?&apos; is for the nominal positions of a 14xx cycle)</source>
        <translation>{1}: o parâmetro {2} ({3}) não pode ser desconhecido (&apos;?&apos; é para as posições nominais de um ciclo 14xx)</translation>
    </message>
</context>
<context>
    <name>kerf::ui::BlockName</name>
    <message>
        <source>line %1</source>
        <translation>linha %1</translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation>Linha %1</translation>
    </message>
    <message>
        <source>Block %1</source>
        <translation>Bloco %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::BlockPrompt</name>
    <message>
        <source>Line</source>
        <translation>Linha</translation>
    </message>
    <message>
        <source>Block number</source>
        <translation>Número do bloco</translation>
    </message>
    <message>
        <source>Block number N</source>
        <translation>Número do bloco N</translation>
    </message>
    <message>
        <source>The program has no block %1</source>
        <translation>O programa não tem o bloco %1</translation>
    </message>
</context>
<context>
    <name>kerf::ui::MachineRows</name>
    <message>
        <source>Increment
continuous</source>
        <translation>Incremento
contínuo</translation>
    </message>
    <message>
        <source>Increment
%1 mm</source>
        <translation>Incremento
%1 mm</translation>
    </message>
    <message>
        <source>Home
all</source>
        <translation>Referenciar
todos</translation>
    </message>
    <message>
        <source>Spindle
on</source>
        <translation>Mandril
ligado</translation>
    </message>
    <message>
        <source>Spindle
off</source>
        <translation>Mandril
desligado</translation>
    </message>
    <message>
        <source>NC
start</source>
        <translation>Arranque
NC</translation>
    </message>
    <message>
        <source>NC stop
(feed hold)</source>
        <translation>Paragem NC
(parar avanço)</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>Continuar</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parar</translation>
    </message>
    <message>
        <source>Start at
block</source>
        <translation>Iniciar no
bloco</translation>
    </message>
    <message>
        <source>Single block
on</source>
        <translation>Bloco a bloco
ligado</translation>
    </message>
    <message>
        <source>Single block
off</source>
        <translation>Bloco a bloco
desligado</translation>
    </message>
    <message>
        <source>Execute
block</source>
        <translation>Executar
bloco</translation>
    </message>
    <message>
        <source>Set preset</source>
        <translation>Definir ponto de referência</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Eixo</translation>
    </message>
    <message>
        <source>Position of %1 at the current point</source>
        <translation>Posição de %1 no ponto atual</translation>
    </message>
    <message>
        <source>Handwheel
axis %1</source>
        <translation>Volante
eixo %1</translation>
    </message>
    <message>
        <source>Step
x%1</source>
        <translation>Passo
x%1</translation>
    </message>
    <message>
        <source>Handwheel
-</source>
        <translation>Volante
-</translation>
    </message>
    <message>
        <source>Handwheel
+</source>
        <translation>Volante
+</translation>
    </message>
    <message>
        <source>Coolant
on</source>
        <translation>Refrigerante
ligado</translation>
    </message>
    <message>
        <source>Coolant
off</source>
        <translation>Refrigerante
desligado</translation>
    </message>
    <message>
        <source>Set
preset</source>
        <translation>Definir
ponto ref.</translation>
    </message>
    <message>
        <source>Spindle speed</source>
        <translation>Rotação do mandril</translation>
    </message>
    <message>
        <source>S in rpm (%1 to %2)</source>
        <translation>S em rpm (%1 a %2)</translation>
    </message>
    <message>
        <source>Probing: the touches give no result</source>
        <translation>Apalpação: os pontos apalpados não dão resultado</translation>
    </message>
    <message>
        <source>Probing ROT</source>
        <translation>Apalpação ROT</translation>
    </message>
    <message>
        <source>Basic rotation in degrees (OK writes it to the preset table)</source>
        <translation>Rotação básica em graus (OK escreve-a na tabela de presets)</translation>
    </message>
    <message>
        <source>Probing CC: diameter %1 mm</source>
        <translation>Apalpação CC: diâmetro %1 mm</translation>
    </message>
    <message>
        <source>Probing</source>
        <translation>Apalpação</translation>
    </message>
    <message>
        <source>Probed %1 = %2: the datum value there</source>
        <translation>Apalpado %1 = %2: valor do ponto de referência aí</translation>
    </message>
    <message>
        <source>Probing
ROT</source>
        <translation>Apalpação
ROT</translation>
    </message>
    <message>
        <source>Probing
POS</source>
        <translation>Apalpação
POS</translation>
    </message>
    <message>
        <source>Probing
P</source>
        <translation>Apalpação
P</translation>
    </message>
    <message>
        <source>Probing
CC</source>
        <translation>Apalpação
CC</translation>
    </message>
    <message>
        <source>Direction
%1</source>
        <translation>Direção
%1</translation>
    </message>
    <message>
        <source>Tool calibration</source>
        <translation>Calibração de ferramentas</translation>
    </message>
    <message>
        <source>Tool offset D</source>
        <translation>Corretor da ferramenta D</translation>
    </message>
    <message>
        <source>Axis touched</source>
        <translation>Eixo tocado</translation>
    </message>
    <message>
        <source>Position of %1 where the tool touches</source>
        <translation>Posição de %1 onde a ferramenta toca</translation>
    </message>
    <message>
        <source>Tool
calibration</source>
        <translation>Calibração
ferramenta</translation>
    </message>
    <message>
        <source>Touch %1
%2/%3</source>
        <translation>Apalpar %1
%2/%3</translation>
    </message>
    <message>
        <source>Tool length
touch-off</source>
        <translation>Comprimento
por toque</translation>
    </message>
    <message>
        <source>Tool length touch-off</source>
        <translation>Medição do comprimento por toque</translation>
    </message>
    <message>
        <source>Z of the surface the tool touches</source>
        <translation>Z da superfície que a ferramenta toca</translation>
    </message>
    <message>
        <source>Probing PL: A %1 degrees, B %2 degrees</source>
        <translation>Apalpação PL: A %1 graus, B %2 graus</translation>
    </message>
    <message>
        <source>Probing
PL</source>
        <translation>Apalpação
PL</translation>
    </message>
    <message>
        <source>Diameter %1 at the current point</source>
        <translation>Diâmetro %1 no ponto atual</translation>
    </message>
    <message>
        <source>Diameter %1 where the tool touches</source>
        <translation>Diâmetro %1 onde a ferramenta toca</translation>
    </message>
</context>
<context>
    <name>kerf::ui::RenumberPrompt</name>
    <message>
        <source>Renumber blocks</source>
        <translation>Renumerar blocos</translation>
    </message>
    <message>
        <source>First block number N</source>
        <translation>Primeiro número de bloco N</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Passo</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 names a label through a parameter, which could not follow it</source>
        <translation>Blocos não renumerados: a linha %1 indica uma etiqueta por meio de um parâmetro, que não poderia segui-la</translation>
    </message>
    <message>
        <source>Blocks not renumbered: the profile of the cycle in line %1 would start or end at N%2; G66, G68 and G69 take labels of 4 digits</source>
        <translation>Blocos não renumerados: o perfil do ciclo na linha %1 começaria ou terminaria em N%2; G66, G68 e G69 admitem etiquetas de 4 dígitos</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 would get N%2, beyond N99999999</source>
        <translation>Blocos não renumerados: a linha %1 receberia N%2, além de N99999999</translation>
    </message>
    <message>
        <source>Blocks not renumbered: line %1 would get N%2, which line %3 carries already; the new line has no block number</source>
        <translation>Blocos não renumerados: a linha %1 receberia N%2, que a linha %3 já tem; a nova linha não tem número de bloco</translation>
    </message>
</context>
</TS>
