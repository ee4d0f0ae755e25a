package io.github.jdem846.view;

/**
 * The pose at which the whole terrain fills the picture: first the distance at which its bounding sphere around
 * the target fits the narrower field of view, then a few steps that scale the distance by how far the projected
 * terrain's bounding box overshoots or undershoots {@value #FILL} of the picture's width or height; last, a lens
 * shift centres that box in the picture.
 */
final class FitDistance {

    private static final double FILL = 0.94;
    private static final int STEPS = 4;

    private FitDistance() {
    }

    static Pose of(Terrain terrain, Camera camera, double[] target) {
        double radius = 0;
        for (int i = 0; i < terrain.size(); i++) {
            if (!Float.isNaN(terrain.z[i])) {
                double dx = terrain.x[i] - target[0];
                double dy = terrain.y[i] - target[1];
                double dz = terrain.z[i] - target[2];
                radius = Math.max(radius, Math.sqrt(dx * dx + dy * dy + dz * dz));
            }
        }
        if (!(radius > 0)) {
            return Pose.of(camera, target, 1);
        }
        double halfV = Math.toRadians(camera.fieldOfViewDegrees()) / 2;
        double halfH = Math.atan(Math.tan(halfV) * camera.width() / camera.height());
        double distance = radius / Math.sin(Math.min(halfV, halfH));
        int step = Math.max(1, (int) Math.sqrt(terrain.size() / 65536.0));
        double[] box = null;
        for (int s = 0; s < STEPS; s++) {
            box = box(terrain, Pose.of(camera, target, distance), step);
            if (box == null) {
                distance *= 2; // part of the terrain is behind the camera: step back
                continue;
            }
            double overshoot = Math.max((box[1] - box[0]) / camera.width(), (box[3] - box[2]) / camera.height());
            if (!(overshoot > 0)) {
                break;
            }
            distance *= Math.max(0.5, Math.min(2, overshoot / FILL));
        }
        Pose pose = Pose.of(camera, target, distance);
        box = box(terrain, pose, step);
        if (box == null) {
            return pose;
        }
        return pose.shifted(camera.width() / 2.0 - 0.5 * (box[0] + box[1]),
                camera.height() / 2.0 - 0.5 * (box[2] + box[3]));
    }

    /**
     * The screen bounding box {minX, maxX, minY, maxY} of every {@code step}-th vertex, or null when one is not in
     * front of the camera.
     */
    private static double[] box(Terrain terrain, Pose pose, int step) {
        double[] box = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY};
        for (int r = 0; r < terrain.height; r = next(r, step, terrain.height)) {
            for (int c = 0; c < terrain.width; c = next(c, step, terrain.width)) {
                int i = r * terrain.width + c;
                if (Float.isNaN(terrain.z[i])) {
                    continue;
                }
                if (!(pose.depth(terrain.x[i], terrain.y[i], terrain.z[i]) > pose.near)) {
                    return null;
                }
                include(box, pose, terrain, i);
            }
        }
        for (int i = terrain.size(); i < terrain.vertexCount(); i++) {
            if (!Float.isNaN(terrain.z[i]) && pose.depth(terrain.x[i], terrain.y[i], terrain.z[i]) > pose.near) {
                include(box, pose, terrain, i); // the base
            }
        }
        return box;
    }

    private static void include(double[] box, Pose pose, Terrain terrain, int i) {
        double x = pose.screenX(terrain.x[i], terrain.y[i], terrain.z[i]);
        double y = pose.screenY(terrain.x[i], terrain.y[i], terrain.z[i]);
        box[0] = Math.min(box[0], x);
        box[1] = Math.max(box[1], x);
        box[2] = Math.min(box[2], y);
        box[3] = Math.max(box[3], y);
    }

    /** The index after {@code i} in steps of {@code step}, always visiting the last, {@code n − 1}. */
    private static int next(int i, int step, int n) {
        return i == n - 1 ? n : Math.min(i + step, n - 1);
    }
}
