// POV-Ray 3.7's Make_Blob (notes: shape-blob.md section 1): the stored element list.
#include "core/scene.h"

namespace povwall {

BlobData make_blob(Real threshold, const std::vector<BlobElement>& components) {
    BlobData d;
    d.threshold = threshold;
    // POV-Ray prepends each component to its list as it parses: the last one comes first.
    for (auto it = components.rbegin(); it != components.rend(); ++it) {
        BlobElement e = *it;
        const Real rad2 = e.rad2, s = e.c[2];
        e.c[0] = s / (rad2 * rad2);
        e.c[1] = -(2.0 * s) / rad2;
        e.c[2] = s;
        d.elements.push_back(e);
        if (e.kind == BlobElementKind::Cylinder) {
            e.kind = BlobElementKind::BaseHemisphere;
            d.elements.push_back(e);
            e.kind = BlobElementKind::ApexHemisphere;
            d.elements.push_back(e);
        }
    }
    return d;
}

}  // namespace povwall
