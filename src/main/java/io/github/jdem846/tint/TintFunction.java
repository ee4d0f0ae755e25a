package io.github.jdem846.tint;

/**
 * Elevation → colour for one DEM (a ramp already bound to that DEM's range). Pure and thread-safe.
 */
@FunctionalInterface
public interface TintFunction {
    /**
     * The non-premultiplied ARGB colour (0xAARRGGBB) of {@code elevation}; NaN (no-data) gives fully transparent
     * 0x00000000 unless the ramp names a colour for no-data.
     *
     * @param elevation the elevation, NaN for no-data
     * @return the colour
     */
    int argb(float elevation);
}
