// Same scene as scene_q4.geo with 8-node serendipity quadrilaterals.
Include "scene_q4.geo";
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;
