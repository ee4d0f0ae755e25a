package io.github.jdem846.sun;

import io.github.jdem846.geo.LatLon;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.util.Objects;
import java.util.Optional;
import net.e175.klaus.solarpositioning.SPA;
import net.e175.klaus.solarpositioning.SunriseResult;

/**
 * The sun's position and the day's sunrise, transit and sunset for one place on the Earth, by NREL's Solar Position
 * Algorithm (I. Reda and A. Andreas, "Solar position algorithm for solar radiation applications", Solar Energy 76
 * (2004) 577–589; ±0.0003° for the years −2000 to 6000). This replaces the original jDem846's NOAA-calculator port,
 * whose Julian day was off by up to a day (docs: jdem846-original.md §4, fault 12).
 *
 * <p>Any time zone works: the same instant gives the same position whatever zone it is written in. For many places
 * at one instant, use {@link SunAtInstant} (or {@link SunPerTile} for a grid).
 */
public final class SolarCalculator {

    private SolarCalculator() {
    }

    /**
     * The topocentric sun (refraction included) at {@code time} seen from ({@code latitude}, {@code longitude}).
     *
     * @param time the instant, in any zone
     * @param latitude degrees north, WGS 84, in [−90, 90]
     * @param longitude degrees east, WGS 84, in [−180, 180]
     * @param observer height, air and ΔT of the observer
     * @return the sun's azimuth (from true north) and zenith angle
     * @throws IllegalArgumentException for a place off the globe, a year outside −2000…6000, or ΔT that must be
     *                                  given (see {@link Observer#deltaTSecondsFor})
     */
    public static SunPosition position(ZonedDateTime time, double latitude, double longitude, Observer observer) {
        return SunAtInstant.of(time, observer).position(latitude, longitude);
    }

    /**
     * The sun at {@code time} seen from {@code place}.
     *
     * @param time the instant, in any zone
     * @param place where the sun is seen from
     * @param observer height, air and ΔT of the observer
     * @return the sun's azimuth (from true north) and zenith angle
     */
    public static SunPosition position(ZonedDateTime time, LatLon place, Observer observer) {
        return position(time, place.latitude(), place.longitude(), observer);
    }

    /**
     * Sunrise, transit and sunset at {@code place} on the calendar day of {@code day} in its own zone, returned in
     * that zone. With a zone far from the place's solar time (e.g. UTC at 179° E), an event may belong to the
     * neighbouring solar day; write the time in the place's own zone to get that day's events.
     *
     * @param day any time on the day; its zone chooses the calendar day and the zone of the results
     * @param place where the sun is seen from
     * @param observer height, air and ΔT of the observer
     * @return the day's kind (regular, polar day or night) and its events
     */
    public static SunEvents events(ZonedDateTime day, LatLon place, Observer observer) {
        Objects.requireNonNull(day, "day");
        Objects.requireNonNull(place, "place");
        SunAtInstant.of(day, observer); // the same year and ΔT checks as for a position
        double deltaT = observer.deltaTSecondsFor(day.withZoneSameInstant(ZoneOffset.UTC).toLocalDate());
        SunriseResult r = SPA.calculateSunriseTransitSet(day, place.latitude(), place.longitude(), deltaT);
        if (r instanceof SunriseResult.RegularDay d) {
            return new SunEvents(SunEvents.DayKind.REGULAR, Optional.of(d.sunrise()), d.transit(),
                    Optional.of(d.sunset()));
        }
        SunEvents.DayKind kind = r instanceof SunriseResult.AllDay ? SunEvents.DayKind.POLAR_DAY
                : SunEvents.DayKind.POLAR_NIGHT;
        return new SunEvents(kind, Optional.empty(), r.transit(), Optional.empty());
    }
}
