package io.github.jdem846.view;

/**
 * Where a {@link Camera} stands and how it projects: eye position and the orthonormal right/up/forward axes in the
 * terrain's local east–north–up frame, and the pinhole projection {@code sx = W/2 + f·x/z}, {@code sy = H/2 − f·y/z}
 * in pixels (pixel centres at +0.5), {@code f = (H/2) / tan(fov/2)}, where x, y, z are the point's coordinates on
 * the camera's right, up and forward axes.
 */
final class Pose {

    final double[] eye;
    final double[] right;
    final double[] up;
    final double[] forward;
    final double focal;
    final double centerX;
    final double centerY;
    /** The near plane: triangles are clipped to the points at least this far along the view axis. */
    final double near;

    private Pose(double[] eye, double[] right, double[] up, double[] forward, double focal, double centerX,
                 double centerY, double near) {
        this.eye = eye;
        this.right = right;
        this.up = up;
        this.forward = forward;
        this.focal = focal;
        this.centerX = centerX;
        this.centerY = centerY;
        this.near = near;
    }

    /**
     * The pose of {@code camera} looking at {@code target} from {@code distance} metres.
     *
     * @param camera   direction, field of view and picture size
     * @param target   the point at the centre of the picture
     * @param distance metres from the target, above 0
     * @return the pose
     */
    static Pose of(Camera camera, double[] target, double distance) {
        double az = Math.toRadians(camera.azimuthDegrees());
        double el = Math.toRadians(camera.elevationDegrees());
        double[] toCamera = {Math.sin(az) * Math.cos(el), Math.cos(az) * Math.cos(el), Math.sin(el)};
        double[] eye = {target[0] + distance * toCamera[0], target[1] + distance * toCamera[1],
            target[2] + distance * toCamera[2]};
        double[] forward = {-toCamera[0], -toCamera[1], -toCamera[2]};
        // right = (horizontal look direction) × up-axis, defined at any elevation up to 90°
        double[] right = {-Math.cos(az), Math.sin(az), 0};
        double[] up = cross(right, forward);
        double focal = camera.height() / 2.0 / Math.tan(Math.toRadians(camera.fieldOfViewDegrees()) / 2);
        return new Pose(eye, right, up, forward, focal, camera.width() / 2.0, camera.height() / 2.0,
                distance * 1e-4);
    }

    /**
     * The pose of a camera at {@code eye} looking at {@code target} (local metres): the right axis is horizontal
     * (forward × up, or east when looking straight down or up), as {@link #of} makes it for the same direction.
     *
     * @param camera field of view and picture size
     * @param eye    where the camera stands
     * @param target the point at the centre of the picture, not at {@code eye}
     * @return the pose
     */
    static Pose lookAt(Camera camera, double[] eye, double[] target) {
        double[] forward = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
        double distance = Math.sqrt(forward[0] * forward[0] + forward[1] * forward[1] + forward[2] * forward[2]);
        if (!(distance > 0)) {
            throw new IllegalArgumentException("the camera stands on the point it looks at: give a look-at point"
                    + " away from the camera's position");
        }
        for (int k = 0; k < 3; k++) {
            forward[k] /= distance;
        }
        double horizontal = Math.hypot(forward[0], forward[1]);
        double[] right = horizontal > 1e-12 ? new double[] {forward[1] / horizontal, -forward[0] / horizontal, 0}
                : new double[] {1, 0, 0};
        double[] up = cross(right, forward);
        double focal = camera.height() / 2.0 / Math.tan(Math.toRadians(camera.fieldOfViewDegrees()) / 2);
        return new Pose(eye.clone(), right, up, forward, focal, camera.width() / 2.0, camera.height() / 2.0,
                distance * 1e-4);
    }

    /**
     * The same camera with the picture's centre moved by ({@code dx}, {@code dy}) pixels (a lens shift: the view
     * direction and the perspective are unchanged).
     */
    Pose shifted(double dx, double dy) {
        return new Pose(eye, right, up, forward, focal, centerX + dx, centerY + dy, near);
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    /** The point's coordinate on the camera's right axis (metres). */
    double cameraX(double x, double y, double z) {
        return (x - eye[0]) * right[0] + (y - eye[1]) * right[1] + (z - eye[2]) * right[2];
    }

    /** The point's coordinate on the camera's up axis (metres). */
    double cameraY(double x, double y, double z) {
        return (x - eye[0]) * up[0] + (y - eye[1]) * up[1] + (z - eye[2]) * up[2];
    }

    /** Depth of a point along the view axis (metres, > 0 in front of the camera). */
    double depth(double x, double y, double z) {
        return (x - eye[0]) * forward[0] + (y - eye[1]) * forward[1] + (z - eye[2]) * forward[2];
    }

    /** Screen x of a point in pixels. */
    double screenX(double x, double y, double z) {
        double cx = (x - eye[0]) * right[0] + (y - eye[1]) * right[1] + (z - eye[2]) * right[2];
        return centerX + focal * cx / depth(x, y, z);
    }

    /** Screen y of a point in pixels, down from the top. */
    double screenY(double x, double y, double z) {
        double cy = (x - eye[0]) * up[0] + (y - eye[1]) * up[1] + (z - eye[2]) * up[2];
        return centerY - focal * cy / depth(x, y, z);
    }

    /** The world direction of the ray through pixel position ({@code sx}, {@code sy}), not normalised. */
    double[] ray(double sx, double sy) {
        double a = (sx - centerX) / focal;
        double b = -(sy - centerY) / focal;
        return new double[] {forward[0] + a * right[0] + b * up[0], forward[1] + a * right[1] + b * up[1],
            forward[2] + a * right[2] + b * up[2]};
    }
}
