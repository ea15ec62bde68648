/* fbx_weights.h -- blend-shape (morph target) weights of one mesh of a
 * binary FBX file, read from the file itself: the static DeformPercent of
 * every BlendShapeChannel and the animation curves that drive it.
 *
 * Why not assimp: assimp 5.2 turns the DeformPercent curves into morph
 * keys, but a channel without a curve (a shape key left at a constant
 * value, which Blender writes as a static DeformPercent and no curve) is
 * missing from its keys and so counted as 0: measured on a Blender cube
 * with "squash" constant at 0.5, the frames came back unsquashed (0.168
 * off).  Here every channel is evaluated, curve or not.
 *
 * What is read (FBX 7.x binary, as Blender and Maya write it; arrays may be
 * zlib-compressed): Model (by name) <- Geometry <- Deformer "BlendShape"
 * <- Deformer "BlendShapeChannel" (DeformPercent; its Shape geometry gives
 * the name assimp uses for the morph target) <-OP "DeformPercent"
 * AnimationCurveNode <-OP "d|DeformPercent" AnimationCurve (KeyTime in
 * 1/46186158000 s, KeyValueFloat in percent, KeyAttrFlags: constant keys
 * hold, linear and cubic keys are joined linearly), and AnimationCurveNode
 * -> AnimationLayer -> AnimationStack: every stack that animates one of the
 * channels is a clip, in file order.  Weights are DeformPercent / 100,
 * given at the union of the key times of the clip's curves.
 *
 * Returns 0 with out filled, 1 if the file is not binary FBX or the model
 * has no blend shapes (out empty), -1 on a damaged file (cm_errmsg()).
 */
#ifndef CM_FBX_WEIGHTS_H
#define CM_FBX_WEIGHTS_H
#ifdef __cplusplus
extern "C" {
#endif

struct fbx_clip {
    char name[128];          /* the AnimationStack's name ("Scene") */
    int nkeys;               /* K >= 1 */
    double *t;               /* K key times in seconds, increasing */
    double *w;               /* K by C weights (DeformPercent / 100) */
};

struct fbx_weights {
    int nchannels;           /* C blend-shape channels of the model */
    char (*names)[128];      /* C names of their shapes (assimp's target names) */
    double *rest;            /* C static weights (DeformPercent / 100) */
    int nclips;              /* stacks animating at least one channel */
    struct fbx_clip *clips;
};

/* path  the .fbx file
 * model the Model's name (assimp's node name), or NULL: the only model
 *       with blend shapes
 * out   the channels and clips (free with fbx_weights_free) */
int fbx_read_weights(const char *path, const char *model, struct fbx_weights *out);
void fbx_weights_free(struct fbx_weights *w);

#ifdef __cplusplus
}
#endif
#endif
