package io.github.jdem846.view;

/**
 * A pinhole camera, placed in one of two ways. By direction: looking at the centre of the terrain (the middle of the
 * grid, at the middle of its range of heights, exaggerated), placed at {@code azimuth} (clockwise from north, the
 * direction the camera stands in as seen from the centre) and {@code elevation} above the horizon, {@code distance}
 * metres from the centre, with a vertical field of view of {@code fieldOfView} degrees; the top of the picture faces
 * away from the camera (azimuth 180°, elevation 90° looks straight down with north up). By position ({@link
 * #lookingAt}): standing at a point and looking at another, given in the DEM's coordinates ({@link LookAt}); the
 * azimuth, elevation and distance are then not used, and the picture's top faces the same way (away from the camera,
 * north up when looking straight down).
 *
 * @param azimuthDegrees   where the camera stands, clockwise from north, any finite value (taken modulo 360)
 * @param elevationDegrees the camera's angle above the horizon at the centre, above 0 and at most 90
 * @param distanceMeters   from the centre of the terrain, above 0; or 0 to fit the whole terrain in the picture
 * @param fieldOfViewDegrees vertical field of view, above 0 and below 180
 * @param width            picture width in pixels, 1 to {@link #MAX_SIDE}
 * @param height           picture height in pixels, 1 to {@link #MAX_SIDE}
 * @param lookAt           where the camera stands and what it looks at, or null to place it by azimuth, elevation
 *                         and distance
 */
public record Camera(double azimuthDegrees, double elevationDegrees, double distanceMeters,
                     double fieldOfViewDegrees, int width, int height, LookAt lookAt) {

    /** Largest picture side, 16384 pixels. */
    public static final int MAX_SIDE = 16384;

    /**
     * Checks the ranges: a finite azimuth, an elevation in (0, 90], a finite distance ≥ 0 and a field of view in (0,
     * 180).
     *
     * @param azimuthDegrees where the camera stands, clockwise from north, any finite value (taken modulo 360)
     * @param elevationDegrees the camera's angle above the horizon at the centre, above 0 and at most 90
     * @param distanceMeters from the centre of the terrain, above 0; or 0 to fit the whole terrain in the picture
     * @param fieldOfViewDegrees vertical field of view, above 0 and below 180
     * @param width picture width in pixels, 1 to {@link #MAX_SIDE}
     * @param height picture height in pixels, 1 to {@link #MAX_SIDE}
     * @param lookAt where the camera stands and what it looks at, or null to place it by azimuth, elevation and
     *     distance
     */
    public Camera {
        if (!Double.isFinite(azimuthDegrees)) {
            throw new IllegalArgumentException("camera azimuth must be a finite number of degrees, got "
                    + azimuthDegrees);
        }
        if (!(elevationDegrees > 0 && elevationDegrees <= 90)) {
            throw new IllegalArgumentException("camera elevation must be above 0 and at most 90 degrees, got "
                    + elevationDegrees);
        }
        if (!(distanceMeters >= 0 && distanceMeters < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("camera distance must be a finite number of metres ≥ 0 (0 = fit the"
                    + " terrain), got " + distanceMeters);
        }
        if (!(fieldOfViewDegrees > 0 && fieldOfViewDegrees < 180)) {
            throw new IllegalArgumentException("field of view must be above 0 and below 180 degrees, got "
                    + fieldOfViewDegrees);
        }
        if (width < 1 || width > MAX_SIDE || height < 1 || height > MAX_SIDE) {
            throw new IllegalArgumentException("picture size must be 1 to " + MAX_SIDE + " pixels a side, got "
                    + width + " × " + height);
        }
    }

    /**
     * A camera placed by azimuth, elevation and distance.
     *
     * @param azimuthDegrees where the camera stands, clockwise from north, any finite value (taken modulo 360)
     * @param elevationDegrees the camera's angle above the horizon at the centre, above 0 and at most 90
     * @param distanceMeters from the centre of the terrain, above 0; or 0 to fit the whole terrain in the picture
     * @param fieldOfViewDegrees vertical field of view, above 0 and below 180
     * @param width picture width in pixels, 1 to {@link #MAX_SIDE}
     * @param height picture height in pixels, 1 to {@link #MAX_SIDE}
     */
    public Camera(double azimuthDegrees, double elevationDegrees, double distanceMeters, double fieldOfViewDegrees,
                  int width, int height) {
        this(azimuthDegrees, elevationDegrees, distanceMeters, fieldOfViewDegrees, width, height, null);
    }

    /**
     * A camera standing at a point and looking at another.
     *
     * @param lookAt             where it stands and what it looks at, in the DEM's coordinates
     * @param fieldOfViewDegrees vertical field of view, above 0 and below 180
     * @param width              picture width in pixels, 1 to {@link #MAX_SIDE}
     * @param height             picture height in pixels, 1 to {@link #MAX_SIDE}
     * @return the camera
     */
    public static Camera lookingAt(LookAt lookAt, double fieldOfViewDegrees, int width, int height) {
        return new Camera(200, 35, 0, fieldOfViewDegrees, width, height, java.util.Objects.requireNonNull(lookAt,
                "lookAt"));
    }

    /**
     * A copy placed by position and look-at point instead.
     *
     * @param value where it stands and what it looks at, or null to place it by azimuth, elevation and distance
     * @return the new camera
     */
    public Camera withLookAt(LookAt value) {
        return new Camera(azimuthDegrees, elevationDegrees, distanceMeters, fieldOfViewDegrees, width, height, value);
    }

    /**
     * A camera that fits the terrain: azimuth 200°, elevation 35°, field of view 40°, 1200 × 800 pixels.
     *
     * @return the camera
     */
    public static Camera defaults() {
        return new Camera(200, 35, 0, 40, 1200, 800);
    }

    /**
     * A copy standing elsewhere.
     *
     * @param azimuth   degrees clockwise from north
     * @param elevation degrees above the horizon
     * @return the new camera
     */
    public Camera withDirection(double azimuth, double elevation) {
        return new Camera(azimuth, elevation, distanceMeters, fieldOfViewDegrees, width, height, lookAt);
    }

    /**
     * A copy at another distance.
     *
     * @param meters from the terrain's centre, or 0 to fit the terrain
     * @return the new camera
     */
    public Camera withDistance(double meters) {
        return new Camera(azimuthDegrees, elevationDegrees, meters, fieldOfViewDegrees, width, height, lookAt);
    }

    /**
     * A copy with another vertical field of view.
     *
     * @param degrees above 0, below 180
     * @return the new camera
     */
    public Camera withFieldOfView(double degrees) {
        return new Camera(azimuthDegrees, elevationDegrees, distanceMeters, degrees, width, height, lookAt);
    }

    /**
     * A copy making a picture of another size.
     *
     * @param w pixels across
     * @param h pixels down
     * @return the new camera
     */
    public Camera withSize(int w, int h) {
        return new Camera(azimuthDegrees, elevationDegrees, distanceMeters, fieldOfViewDegrees, w, h, lookAt);
    }

    /** {@return true when the distance is chosen to fit the terrain (a camera placed by direction, distance 0)} */
    public boolean fits() {
        return lookAt == null && distanceMeters == 0;
    }
}
