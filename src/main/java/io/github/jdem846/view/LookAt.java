package io.github.jdem846.view;

/**
 * A camera placed by where it stands and the point it looks at, both in the DEM's CRS units (the units of its
 * geotransform: metres of a projected grid, degrees of a latitude/longitude one, as {@code --window} takes them),
 * with heights in the DEM's height units above its datum. Heights are exaggerated as the terrain is ({@link
 * ViewOptions#exaggeration()}), so a camera 100 m above a valley floor stays above it at any exaggeration.
 *
 * @param x       the camera's easting (or longitude)
 * @param y       the camera's northing (or latitude)
 * @param z       the camera's height
 * @param targetX the looked-at point's easting (or longitude)
 * @param targetY the looked-at point's northing (or latitude)
 * @param targetZ the looked-at point's height, or NaN for the terrain's height there (the middle of its range of
 *                heights when that point is outside the grid or no-data)
 */
public record LookAt(double x, double y, double z, double targetX, double targetY, double targetZ) {

    /**
     * Checks that the coordinates are finite (the target's height may be NaN).
     *
     * @param x       the camera's easting (or longitude)
     * @param y       the camera's northing (or latitude)
     * @param z       the camera's height
     * @param targetX the looked-at point's easting (or longitude)
     * @param targetY the looked-at point's northing (or latitude)
     * @param targetZ the looked-at point's height, or NaN for the terrain's height there
     */
    public LookAt {
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
            throw new IllegalArgumentException("camera position must be three finite numbers, got " + x + ", " + y
                    + ", " + z);
        }
        if (!Double.isFinite(targetX) || !Double.isFinite(targetY) || Double.isInfinite(targetZ)) {
            throw new IllegalArgumentException("look-at point must be finite numbers, got " + targetX + ", "
                    + targetY + ", " + targetZ);
        }
    }

    /**
     * A camera at ({@code x}, {@code y}, {@code z}) looking at the terrain at ({@code targetX}, {@code targetY}).
     *
     * @param x       the camera's easting (or longitude)
     * @param y       the camera's northing (or latitude)
     * @param z       the camera's height
     * @param targetX the looked-at point's easting (or longitude)
     * @param targetY the looked-at point's northing (or latitude)
     * @return the placement, its target on the terrain
     */
    public static LookAt onTerrain(double x, double y, double z, double targetX, double targetY) {
        return new LookAt(x, y, z, targetX, targetY, Double.NaN);
    }

    /** {@return true when the target's height is the terrain's there} */
    public boolean targetOnTerrain() {
        return Double.isNaN(targetZ);
    }
}
