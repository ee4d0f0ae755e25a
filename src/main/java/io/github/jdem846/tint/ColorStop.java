package io.github.jdem846.tint;

import java.util.Objects;

/**
 * One stop of a {@link ColorRamp}: at {@code level} the ramp has colour {@code argb} (non-premultiplied
 * 0xAARRGGBB).
 *
 * @param level a percent of the DEM's range in [0, 100] ({@link StopUnit#PERCENT}) or an elevation
 *              ({@link StopUnit#ABSOLUTE}); finite
 * @param unit  what {@code level} measures
 * @param argb  the colour at the stop
 */
public record ColorStop(double level, StopUnit unit, int argb) {

    /**
     * Checks that the unit is given, the level finite and a percent level in [0, 100].
     *
     * @param level a percent of the DEM's range in [0, 100] ({@link StopUnit#PERCENT}) or an elevation ({@link
     *     StopUnit#ABSOLUTE}); finite
     * @param unit what {@code level} measures
     * @param argb the colour at the stop
     */
    public ColorStop {
        Objects.requireNonNull(unit, "unit");
        if (!Double.isFinite(level)) {
            throw new IllegalArgumentException("a colour stop's level must be a finite number, got " + level);
        }
        if (unit == StopUnit.PERCENT && (level < 0 || level > 100)) {
            throw new IllegalArgumentException("a percent stop must lie in [0, 100], got " + level + "%");
        }
    }

    /**
     * An opaque stop at {@code percent} of the DEM's range.
     *
     * @param percent the stop's place in the DEM's range, 0 to 100
     * @param red red, 0 to 255
     * @param green green, 0 to 255
     * @param blue blue, 0 to 255
     * @return the stop
     */
    public static ColorStop percent(double percent, int red, int green, int blue) {
        return new ColorStop(percent, StopUnit.PERCENT, rgba(red, green, blue, 255));
    }

    /**
     * An opaque stop at elevation {@code elevation}.
     *
     * @param elevation the stop's elevation, in the DEM's units; finite
     * @param red red, 0 to 255
     * @param green green, 0 to 255
     * @param blue blue, 0 to 255
     * @return the stop
     */
    public static ColorStop absolute(double elevation, int red, int green, int blue) {
        return new ColorStop(elevation, StopUnit.ABSOLUTE, rgba(red, green, blue, 255));
    }

    /**
     * Packs 0–255 channels into 0xAARRGGBB, rejecting values outside 0–255.
     *
     * @param red red, 0 to 255
     * @param green green, 0 to 255
     * @param blue blue, 0 to 255
     * @param alpha opacity, 0 (transparent) to 255 (opaque)
     * @return the packed colour
     */
    public static int rgba(int red, int green, int blue, int alpha) {
        checkChannel("red", red);
        checkChannel("green", green);
        checkChannel("blue", blue);
        checkChannel("alpha", alpha);
        return Argb.of(red, green, blue, alpha);
    }

    /** {@return the red channel, 0 to 255} */
    public int red() {
        return Argb.red(argb);
    }

    /** {@return the green channel, 0 to 255} */
    public int green() {
        return Argb.green(argb);
    }

    /** {@return the blue channel, 0 to 255} */
    public int blue() {
        return Argb.blue(argb);
    }

    /** {@return the opacity, 0 (transparent) to 255 (opaque)} */
    public int alpha() {
        return Argb.alpha(argb);
    }

    @Override
    public String toString() {
        return (unit == StopUnit.PERCENT ? level + "%" : level + "") + " " + Argb.format(argb);
    }

    private static void checkChannel(String name, int value) {
        if (value < 0 || value > 255) {
            throw new IllegalArgumentException(name + " must be an integer 0–255, got " + value);
        }
    }
}
