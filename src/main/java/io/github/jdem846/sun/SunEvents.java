package io.github.jdem846.sun;

import java.time.ZonedDateTime;
import java.util.Objects;
import java.util.Optional;

/**
 * Sunrise, transit (solar noon) and sunset of one calendar day, in the time zone of the time they were asked for.
 * Sunrise and sunset are when the sun's upper limb touches a sea-level horizon, refraction included (the sun's
 * centre at −0.8334°, as almanacs print them). On a polar day or night there is neither; the transit is always
 * there (below the horizon on a polar night).
 *
 * @param kind    regular day, polar day or polar night
 * @param sunrise the sunrise, empty unless {@link DayKind#REGULAR}
 * @param transit the sun's transit across the local meridian
 * @param sunset  the sunset, empty unless {@link DayKind#REGULAR}
 */
public record SunEvents(DayKind kind, Optional<ZonedDateTime> sunrise, ZonedDateTime transit,
                        Optional<ZonedDateTime> sunset) {

    /** Whether the sun rises and sets on the day. */
    public enum DayKind {
        /** The sun rises and sets. */
        REGULAR,
        /** Midnight sun: the sun stays above the horizon all day (no sunrise, no sunset). */
        POLAR_DAY,
        /** Polar night: the sun stays below the horizon all day (no sunrise, no sunset). */
        POLAR_NIGHT
    }

    /**
     * Checks that the kind and the three times are given.
     *
     * @param kind regular day, polar day or polar night
     * @param sunrise the sunrise, empty unless {@link DayKind#REGULAR}
     * @param transit the sun's transit across the local meridian
     * @param sunset the sunset, empty unless {@link DayKind#REGULAR}
     */
    public SunEvents {
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(sunrise, "sunrise");
        Objects.requireNonNull(transit, "transit");
        Objects.requireNonNull(sunset, "sunset");
        if ((kind == DayKind.REGULAR) != (sunrise.isPresent() && sunset.isPresent())
                || sunrise.isPresent() != sunset.isPresent()) {
            throw new IllegalArgumentException("a " + kind + " day must have both a sunrise and a sunset exactly "
                    + "when it is REGULAR");
        }
    }
}
