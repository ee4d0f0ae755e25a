package io.github.jdem846.tint;

/**
 * How a colour is chosen for an elevation that lies between two stops; the three modes of
 * {@code gdaldem color-relief}.
 */
public enum ColorSelection {
    /** Linear interpolation in RGB and alpha between the two stops around the elevation (gdaldem's default). */
    INTERPOLATE,
    /** The colour of the nearer stop; a tie goes to the upper stop ({@code gdaldem -nearest_color_entry}). */
    NEAREST,
    /**
     * Only an elevation equal to a stop gets that stop's colour; every other elevation is transparent
     * ({@code gdaldem -exact_color_entry}, as fixed in GDAL 3.9.2).
     */
    EXACT
}
