// The knobs of the octree's labels (common/octree_labels.glsl):
// octree_label.comp's uniform `rule`, set by StepStructureStage, and the
// native loop's argument (render/stages/NativeStepStructure.h).
struct OctreeLabelRule {
    float epsilon;
    float epsilon_prime;
    float index_scale;  // largest dispersion scale: ranges are of n = n_ref + s·δn
    float capped_step;  // metres
    float min_step;     // metres, Δs_min
    float node_edge;    // metres, the diagonal of a level-0 node
    float optical_depth_tolerance;
};

