<?xml version="1.0" encoding="utf-8"?>
<!-- SPDX-License-Identifier: LGPL-2.1-or-later -->
<!DOCTYPE TS>
<TS version="2.1">
<context>
    <name>App::Property</name>
    <message>
        <location filename="../../App/sliceform_app/children.py" line="74"/>
        <source>The sliceform this patch belongs to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/children.py" line="74"/>
        <source>Position of the patch in the design</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/children.py" line="74"/>
        <source>The id engraved on the patch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/children.py" line="114"/>
        <source>The patch shown on its sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/making.py" line="45"/>
        <source>Which sheet of the layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/making.py" line="43"/>
        <source>The sliceform whose sheet this page shows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/making.py" line="47"/>
        <source>The sheet&apos;s size and margin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/feature.py" line="41"/>
        <source>The solid, body or mesh to design a sliceform for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/feature.py" line="64"/>
        <source>Patches and pages made for the design</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="44"/>
        <source>Custom sheet width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="44"/>
        <source>Custom sheet height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>Patches in the design</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>The slotted design is rigid apart from the fold (certificate nullity 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>Interlocked loop pairs left: the design cannot be assembled if &gt; 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>Smallest paper left beside a slot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>Shortest holding hinge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>Closest two patches of one family that overlap seen along their normal (0: none do)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>Paper left between their slots on a common partner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>The design meets every rule of the fabrication contract</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>Volume IoU of the sliceform against the source (1 = perfect)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>Sheets used by the layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>With Directions auto: the frame chosen, its U and V, and why it won</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/parameters.py" line="81"/>
        <source>Summary of the last recompute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="4"/>
        <source>given: slice along u and v; auto: try the model&apos;s principal axes and the file&apos;s axes, each up and the families turned about it, and keep the buildable frame that scores best (1.5-3 times the time of one design)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="6"/>
        <source>normal of the U family of patches, x,y,z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="8"/>
        <source>normal of the V family, x,y,z, orthogonal to U (W = U x V is up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="12"/>
        <source>slices per direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="14"/>
        <source>mm between slices; overrides slices (0: slices sets it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="16"/>
        <source>cylinder error budget, relative to each part&apos;s volume (the paper&apos;s tauA)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="18"/>
        <source>Reeb branch merge threshold, a weight ratio (the paper&apos;s tauM)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="20"/>
        <source>both families, or u / v for one dominant direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="22"/>
        <source>scale the model so its longest side is this many mm (0: keep its size; mesh files carry no unit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="24"/>
        <source>seconds the design may take before its searches stop with the best found, which is not called buildable (0: no limit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="26"/>
        <source>mm a hinge must be long to carry load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="28"/>
        <source>mm of paper to keep on each side of a slot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="30"/>
        <source>mm between two patches of one family that overlap seen along their normal, so paper is left between their slots (0: slot width + min slot-edge distance)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="32"/>
        <source>mm; add patches in long cylinders so none is farther apart (0: off)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="34"/>
        <source>mm of material (0.3 for card, 3 for plywood)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="36"/>
        <source>mm added to the thickness for the slot width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="38"/>
        <source>mm the cutter removes; cut paths are moved out by half</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="40"/>
        <source>square, or round closed slot ends</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="42"/>
        <source>up or down: which way U-patches are slotted first (V the other way)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="44"/>
        <source>sheet size: A4, A3, Letter, or WxH in mm (e.g. 600x400)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="46"/>
        <source>mm kept clear along every sheet edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="48"/>
        <source>mm between patches on a sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="50"/>
        <source>patches may be turned by quarters to nest better; off (--no-rotate) keeps every patch upright on the sheet (grain, printed textures)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="52"/>
        <source>degrees between the families in the 3D assembly: 90 is popped up, small angles fold it flat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/children.py" line="143"/>
        <source>The patch whose labels these are</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/children.py" line="143"/>
        <source>Which part of the patch&apos;s engraving this is (0: the first)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="10"/>
        <source>fill every hole of a mesh, not only those up to 20 % of its size across, with a fan of triangles about its centre (flat where the rim is)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Sliceform</name>
    <message>
        <location filename="../../Gui/sliceform_gui/assembly_steps.py" line="75"/>
        <source>Assembly steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/assembly_steps.py" line="81"/>
        <source>Previous</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/assembly_steps.py" line="82"/>
        <source>Next</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="36"/>
        <source>select a solid, a PartDesign body or a closed mesh first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="180"/>
        <source>Export the layout into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="190"/>
        <source>Sliceform: wrote {} files into {}: {}</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/task_panel.py" line="108"/>
        <source>Error: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="294"/>
        <source>{} report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="295"/>
        <source>Not computed yet: recompute the sliceform.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="296"/>
        <source>Save report.json...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="308"/>
        <source>Save report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="308"/>
        <source>JSON (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/task_panel.py" line="22"/>
        <source>Custom sheet width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/task_panel.py" line="23"/>
        <source>Custom sheet height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="19"/>
        <source>Scheme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="43"/>
        <source>Sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="39"/>
        <source>Slot ends</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/task_panel.py" line="52"/>
        <source>Sliceform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/task_panel.py" line="73"/>
        <source>Recompute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/task_panel.py" line="106"/>
        <source>Not computed yet: press Recompute.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/children.py" line="82"/>
        <source>this patch&apos;s sliceform was deleted: delete the patch too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/children.py" line="122"/>
        <source>this drawing&apos;s patch or sliceform was deleted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/feature.py" line="108"/>
        <source>the sliceform has no Source: link a solid, body or mesh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/feature.py" line="404"/>
        <source>cannot be built: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/feature.py" line="404"/>
        <source>see the report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/shapes.py" line="17"/>
        <source>{} has no shape</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="3"/>
        <source>Directions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="5"/>
        <source>UDirection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="7"/>
        <source>VDirection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="11"/>
        <source>Slices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="13"/>
        <source>Interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="15"/>
        <source>Cylinder error budget</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="17"/>
        <source>Branch merge threshold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="21"/>
        <source>Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="23"/>
        <source>Time limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="25"/>
        <source>Shortest hinge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="27"/>
        <source>Paper beside a slot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="29"/>
        <source>Closest patches</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="31"/>
        <source>Farthest patches</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="33"/>
        <source>Thickness</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="35"/>
        <source>Slot clearance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="37"/>
        <source>Cutter kerf</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="41"/>
        <source>U slots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="45"/>
        <source>Sheet margin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="47"/>
        <source>Space between patches</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="49"/>
        <source>Rotate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="51"/>
        <source>Fold angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../App/sliceform_app/children.py" line="153"/>
        <source>this engraving&apos;s patch or sliceform was deleted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/preferences.py" line="31"/>
        <source>Defaults for new sliceforms (material, sheets, slicing)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../build/translations/schema_strings.py" line="9"/>
        <source>Fill every hole</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Sliceform_AssemblySteps</name>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="324"/>
        <source>Assembly steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="325"/>
        <source>Step through the selected sliceform&apos;s assembly order: the patches placed so far, the new one in orange, and the partners its slots go onto (a display mode: the document is not changed)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Sliceform_Create</name>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="96"/>
        <source>Create sliceform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="98"/>
        <source>Design a paper sliceform of the selected solid, PartDesign body or closed mesh: slotted patches, each on its plane and on its sheet, and a TechDraw page per sheet. It follows the source when the source changes.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Sliceform_Edit</name>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="148"/>
        <source>Edit sliceform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="149"/>
        <source>Change the selected sliceform&apos;s parameters in the task panel, recompute and see the results (stability, interlocks, slot distances, sheets)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Sliceform_Export</name>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="166"/>
        <source>Export layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="168"/>
        <source>Write the selected sliceform&apos;s sheets into a folder: DXF per sheet for laser cutters (layers CUT and ENGRAVE, mm), SVG per sheet, a PDF to print at 100 %, PNG previews, STEP/glTF of the assembly and report.json</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Sliceform_Fold</name>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="212"/>
        <source>Fold animation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="213"/>
        <source>Animate the selected sliceform folding flat and popping up again (FoldAngle 90 to 10 degrees and back in 2 s; the angle is restored after). Run it again to stop.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Sliceform_Report</name>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="280"/>
        <source>Show report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="281"/>
        <source>Show the selected sliceform&apos;s checks: stability certificate, interlocks, split patches, slot-to-edge distance, hinge lengths, quality, sheets; save report.json</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Sliceform_Slices</name>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="63"/>
        <source>Slices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../Gui/sliceform_gui/commands.py" line="64"/>
        <source>Cut the selected solid or closed mesh into 16 sections along X and 16 along Y and add them as one compound (exact curves for CAD solids)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Workbench</name>
    <message>
        <location filename="../../InitGui.py" line="9"/>
        <source>Sliceform</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../InitGui.py" line="10"/>
        <source>Turn a solid into a paper sliceform: slotted patches that fold flat</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
