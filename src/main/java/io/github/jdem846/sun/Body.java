package io.github.jdem846.sun;

import io.github.jdem846.geo.Ellipsoid;
import java.util.Locale;
import java.util.Objects;

/**
 * The body a DEM lies on: its figure, and whether this library can place the sun in its sky from a date and time
 * (only the Earth: the SPA is an Earth ephemeris). A DEM of the Moon or Mars can still be lit by a sun given as
 * azimuth and elevation.
 *
 * @param name      a name for messages, e.g. "Moon"
 * @param ellipsoid its figure
 * @param isEarth   true for the Earth, the only body with sun positions by date and time
 */
public record Body(String name, Ellipsoid ellipsoid, boolean isEarth) {

    /** The Earth, WGS 84. */
    public static final Body EARTH = new Body("Earth", Ellipsoid.WGS84, true);
    /** The Moon, a sphere of 1737.4 km. */
    public static final Body MOON = new Body("Moon", Ellipsoid.MOON, false);
    /** Mars, a sphere of 3389.5 km. */
    public static final Body MARS = new Body("Mars", Ellipsoid.MARS, false);

    /**
     * Checks that the name and the figure are given.
     *
     * @param name a name for messages, e.g. "Moon"
     * @param ellipsoid its figure
     * @param isEarth true for the Earth, the only body with sun positions by date and time
     */
    public Body {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(ellipsoid, "ellipsoid");
    }

    /**
     * {@code earth}, {@code moon} or {@code mars}, in any case.
     *
     * @param name the body's name, {@code null} or any other name is refused
     * @return the matching constant ({@link #EARTH}, {@link #MOON} or {@link #MARS})
     * @throws IllegalArgumentException for any other name, with the names that are accepted
     */
    public static Body named(String name) {
        String n = name == null ? "" : name.strip().toLowerCase(Locale.ROOT);
        return switch (n) {
            case "earth" -> EARTH;
            case "moon" -> MOON;
            case "mars" -> MARS;
            default -> throw new IllegalArgumentException("unknown body '" + name + "': expected earth, moon or "
                    + "mars (or give a radius in metres)");
        };
    }

    /**
     * A spherical body of {@code radiusMeters} other than the Earth (no sun positions by date and time).
     *
     * @param radiusMeters the sphere's radius in metres; positive and finite
     * @return a body without sun positions by date and time
     * @throws IllegalArgumentException when the radius is not positive and finite
     */
    public static Body sphere(double radiusMeters) {
        if (!(radiusMeters > 0) || Double.isInfinite(radiusMeters)) {
            throw new IllegalArgumentException("body radius must be a positive number of metres, got "
                    + radiusMeters);
        }
        return new Body("a body of radius " + radiusMeters + " m", Ellipsoid.sphere("sphere", radiusMeters),
                false);
    }

    /** {@return the mean radius in metres} */
    public double radiusMeters() {
        return ellipsoid.meanRadius();
    }

    /**
     * Returns this body when the sun can be placed in its sky from a date and time.
     *
     * @return this body
     * @throws IllegalArgumentException naming the body and what to do instead
     */
    public Body requireSunByDateAndTime() {
        if (!isEarth) {
            throw new IllegalArgumentException("sun positions from a date and time are computed for the Earth only "
                    + "(NREL SPA is an Earth ephemeris), not for " + name + "; give the sun's azimuth and "
                    + "elevation instead");
        }
        return this;
    }
}
