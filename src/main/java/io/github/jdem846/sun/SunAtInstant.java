package io.github.jdem846.sun;

import io.github.jdem846.geo.LatLon;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.util.Objects;
import net.e175.klaus.solarpositioning.SPA;
import net.e175.klaus.solarpositioning.SolarPosition;

/**
 * The sun at one instant, seen by one {@link Observer}, ready to be placed anywhere on the Earth: the
 * time-dependent half of the SPA (heliocentric position, nutation, sidereal time) is computed once here, and
 * {@link #position(double, double)} adds the place-dependent half (hour angle, parallax, refraction), about ten
 * times faster than a full computation. Immutable and thread-safe.
 */
public final class SunAtInstant {

    /** First year for which the SPA is specified. */
    public static final int FIRST_YEAR = -2000;
    /** Last year for which the SPA is specified. */
    public static final int LAST_YEAR = 6000;

    private final ZonedDateTime time;
    private final Observer observer;
    private final double deltaTSeconds;
    private final SPA.SpaTimeDependent parts;

    private SunAtInstant(ZonedDateTime time, Observer observer) {
        this.time = time;
        this.observer = observer;
        this.deltaTSeconds = observer.deltaTSecondsFor(time.withZoneSameInstant(ZoneOffset.UTC).toLocalDate());
        this.parts = SPA.calculateSpaTimeDependentParts(time, deltaTSeconds);
    }

    /**
     * The sun at {@code time} for {@code observer}.
     *
     * @param time the instant, in any zone
     * @param observer height, air and ΔT of the observer
     * @return the sun at that instant, ready for positions at any place
     * @throws IllegalArgumentException when the year is outside the SPA's −2000 to 6000, or ΔT is not given and
     *                                  cannot be estimated for the date
     */
    public static SunAtInstant of(ZonedDateTime time, Observer observer) {
        Objects.requireNonNull(time, "time");
        Objects.requireNonNull(observer, "observer");
        int year = time.withZoneSameInstant(ZoneOffset.UTC).getYear();
        if (year < FIRST_YEAR || year > LAST_YEAR) {
            throw new IllegalArgumentException("the solar position algorithm covers the years " + FIRST_YEAR
                    + " to " + LAST_YEAR + ", got " + time);
        }
        return new SunAtInstant(time, observer);
    }

    /** {@return the instant, in the zone it was given in} */
    public ZonedDateTime time() {
        return time;
    }

    /** {@return the observer the positions are computed for} */
    public Observer observer() {
        return observer;
    }

    /** {@return ΔT used, in seconds (given or estimated)} */
    public double deltaTSeconds() {
        return deltaTSeconds;
    }

    /**
     * The sun seen from latitude {@code latitude} and longitude {@code longitude} (degrees, WGS 84, north and east
     * positive).
     *
     * @param latitude degrees north
     * @param longitude degrees east
     * @return the sun's azimuth (from true north) and zenith angle
     * @throws IllegalArgumentException when the latitude is outside [−90, 90] or the longitude outside
     *                                  [−180, 180] (wrap grid longitudes with {@link LatLon#wrapLongitude})
     */
    public SunPosition position(double latitude, double longitude) {
        LatLon.validated(latitude, longitude); // a message for a person when out of range
        SolarPosition p = SPA.calculateSolarPositionWithTimeDependentParts(latitude, longitude,
                observer.heightMeters(), observer.pressureMillibars(), observer.temperatureCelsius(), parts);
        return new SunPosition(p.azimuth(), Math.max(0, Math.min(180, p.zenithAngle())));
    }

    /**
     * The sun seen from {@code place}.
     *
     * @param place where the sun is seen from
     * @return the sun's azimuth (from true north) and zenith angle
     */
    public SunPosition position(LatLon place) {
        return position(place.latitude(), place.longitude());
    }
}
