package io.github.jdem846.sun;

import io.github.jdem846.geo.LatLon;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import org.junit.jupiter.api.Test;

/**
 * Against independent references: the SPA paper's worked example, PyEphem 4.2.1 (a different engine, VSOP87, USNO
 * rise/set convention; testdata/golden/sun/README.md has the script and its output) and a published almanac value.
 */
class SolarCalculatorTest {

    private static final LatLon GOLDEN_CO = new LatLon(39.742476, -105.1786);
    private static final LatLon LUXEMBOURG = new LatLon(49.6116, 6.1319);
    private static final LatLon LONGYEARBYEN = new LatLon(78.22, 15.65);

    @Test
    void spaPaperWorkedExample() {
        // The worked example of Reda & Andreas, NREL/TP-560-34302 (rev. 2008): zenith 50.11162°, azimuth 194.34024°.
        Observer o = new Observer(1830.14, 820, 11, java.util.OptionalDouble.of(67));
        SunPosition p = SolarCalculator.position(ZonedDateTime.parse("2003-10-17T12:30:30-07:00"), GOLDEN_CO, o);
        assertEquals(50.11162, p.zenithDegrees(), 1e-3);
        assertEquals(194.34024, p.azimuthDegrees(), 1e-3);
        assertEquals(90 - 50.11162, p.elevationDegrees(), 1e-3);
    }

    @Test
    void spaExampleDayEventsMatchPyEphem() {
        // PyEphem: rise 13:12:44Z, transit 18:46:05Z, set 00:18:51Z next day (= 06:12:44, 11:46:05, 17:18:51 −07:00)
        SunEvents e = SolarCalculator.events(ZonedDateTime.parse("2003-10-17T12:30:30-07:00"), GOLDEN_CO,
                Observer.SEA_LEVEL.withDeltaT(67));
        assertEquals(SunEvents.DayKind.REGULAR, e.kind());
        assertNear(ZonedDateTime.parse("2003-10-17T06:12:44-07:00"), e.sunrise().orElseThrow(), 60);
        assertNear(ZonedDateTime.parse("2003-10-17T11:46:05-07:00"), e.transit(), 60);
        assertNear(ZonedDateTime.parse("2003-10-17T17:18:51-07:00"), e.sunset().orElseThrow(), 60);
    }

    @Test
    void luxembourgSunriseAtJuneSolstice() {
        // PyEphem for 49.6116 N 6.1319 E: rise 03:28:15Z, transit 11:37:23Z, set 19:46:31Z (CEST = UTC+2).
        ZonedDateTime day = ZonedDateTime.of(2024, 6, 21, 12, 0, 0, 0, ZoneId.of("Europe/Luxembourg"));
        SunEvents e = SolarCalculator.events(day, LUXEMBOURG, Observer.SEA_LEVEL);
        ZonedDateTime sunrise = e.sunrise().orElseThrow();
        assertEquals(ZoneId.of("Europe/Luxembourg"), sunrise.getZone(), "events come back in the input's zone");
        assertNear(ZonedDateTime.parse("2024-06-21T05:28:15+02:00[Europe/Luxembourg]"), sunrise, 120);
        assertNear(ZonedDateTime.parse("2024-06-21T13:37:23+02:00[Europe/Luxembourg]"), e.transit(), 120);
        assertNear(ZonedDateTime.parse("2024-06-21T21:46:31+02:00[Europe/Luxembourg]"), e.sunset().orElseThrow(),
                120);
    }

    @Test
    void zurichSolsticeMatchesPublishedAlmanac() {
        // Meteonews via 24heures.ch (2018-06): Zurich, 21 June 2018, sunrise 05:29, sunset 21:26 (to the minute).
        ZonedDateTime day = ZonedDateTime.of(2018, 6, 21, 12, 0, 0, 0, ZoneId.of("Europe/Zurich"));
        SunEvents e = SolarCalculator.events(day, new LatLon(47.3769, 8.5417), Observer.SEA_LEVEL);
        assertNear(day.withHour(5).withMinute(29), e.sunrise().orElseThrow(), 120);
        assertNear(day.withHour(21).withMinute(26), e.sunset().orElseThrow(), 120);
    }

    @Test
    void svalbardPolarNightInDecemberAndPolarDayInJune() {
        ZoneId oslo = ZoneId.of("Europe/Oslo");
        ZonedDateTime december = ZonedDateTime.of(2024, 12, 21, 0, 0, 0, 0, oslo);
        SunEvents night = SolarCalculator.events(december, LONGYEARBYEN, Observer.SEA_LEVEL);
        assertEquals(SunEvents.DayKind.POLAR_NIGHT, night.kind());
        assertTrue(night.sunrise().isEmpty() && night.sunset().isEmpty());
        ZonedDateTime june = ZonedDateTime.of(2024, 6, 21, 0, 0, 0, 0, oslo);
        SunEvents day = SolarCalculator.events(june, LONGYEARBYEN, Observer.SEA_LEVEL);
        assertEquals(SunEvents.DayKind.POLAR_DAY, day.kind());
        assertTrue(day.sunrise().isEmpty() && day.sunset().isEmpty());
        for (int minute = 0; minute < 24 * 60; minute += 20) {
            SunPosition dec = SolarCalculator.position(december.plusMinutes(minute), LONGYEARBYEN,
                    Observer.SEA_LEVEL);
            SunPosition jun = SolarCalculator.position(june.plusMinutes(minute), LONGYEARBYEN, Observer.SEA_LEVEL);
            assertTrue(dec.elevationDegrees() < 0 && dec.isBelowHorizon(), "December sun up at +" + minute);
            assertTrue(dec.toLightDirection().isBelowHorizon());
            assertTrue(jun.elevationDegrees() > 0 && !jun.isBelowHorizon(), "June sun down at +" + minute);
        }
    }

    @Test
    void southernPolarSeasonsAreMirrored() {
        LatLon antarctic = new LatLon(-78.22, 15.65);
        SunEvents june = SolarCalculator.events(ZonedDateTime.parse("2024-06-21T12:00Z"), antarctic,
                Observer.SEA_LEVEL);
        SunEvents december = SolarCalculator.events(ZonedDateTime.parse("2024-12-21T12:00Z"), antarctic,
                Observer.SEA_LEVEL);
        assertEquals(SunEvents.DayKind.POLAR_NIGHT, june.kind());
        assertEquals(SunEvents.DayKind.POLAR_DAY, december.kind());
    }

    @Test
    void morningSunIsEastNoonSunSouthInTheNorthAndNorthInTheSouthEveningSunWest() {
        record Place(LatLon at, ZoneId zone, double noonAzimuth) {
        }
        Place[] places = {
            new Place(LUXEMBOURG, ZoneId.of("Europe/Luxembourg"), 180),
            new Place(GOLDEN_CO, ZoneId.of("America/Denver"), 180),
            new Place(new LatLon(-33.92, 18.42), ZoneId.of("Africa/Johannesburg"), 0), // Cape Town
            new Place(new LatLon(-36.85, 174.76), ZoneId.of("Pacific/Auckland"), 0),
        };
        for (Place place : places) {
            for (int month = 1; month <= 12; month += 3) {
                ZonedDateTime day = ZonedDateTime.of(2024, month, 15, 12, 0, 0, 0, place.zone());
                ZonedDateTime transit = SolarCalculator.events(day, place.at(), Observer.SEA_LEVEL).transit();
                SunPosition morning = SolarCalculator.position(transit.minusHours(3), place.at(), Observer.SEA_LEVEL);
                SunPosition noon = SolarCalculator.position(transit, place.at(), Observer.SEA_LEVEL);
                SunPosition evening = SolarCalculator.position(transit.plusHours(3), place.at(), Observer.SEA_LEVEL);
                String where = place.at() + " " + day.toLocalDate();
                assertTrue(morning.azimuthDegrees() > 0 && morning.azimuthDegrees() < 180, "morning east " + where);
                assertTrue(evening.azimuthDegrees() > 180 && evening.azimuthDegrees() < 360, "evening west " + where);
                double offNoon = Math.abs(((noon.azimuthDegrees() - place.noonAzimuth() + 540) % 360) - 180);
                assertTrue(offNoon < 0.5, "noon azimuth " + noon.azimuthDegrees() + " at " + where);
            }
        }
    }

    @Test
    void tropicalNoonSunIsNorthWhenTheDeclinationExceedsTheLatitude() {
        LatLon tenNorth = new LatLon(10, 0);
        ZonedDateTime transit = SolarCalculator.events(ZonedDateTime.parse("2024-06-21T12:00Z"), tenNorth,
                Observer.SEA_LEVEL).transit();
        SunPosition noon = SolarCalculator.position(transit, tenNorth, Observer.SEA_LEVEL);
        assertTrue(noon.azimuthDegrees() < 1 || noon.azimuthDegrees() > 359, "azimuth " + noon.azimuthDegrees());
        // elevation at transit = 90 − |φ − δ| with δ ≈ 23.44° on the solstice
        assertEquals(90 - (23.44 - 10), noon.elevationDegrees(), 0.05);
    }

    @Test
    void sameInstantInAnyZoneGivesTheSamePosition() {
        ZonedDateTime utc = ZonedDateTime.parse("2024-06-21T10:15:30Z");
        ZonedDateTime[] same = {
            utc,
            utc.withZoneSameInstant(ZoneOffset.ofHours(-7)),
            utc.withZoneSameInstant(ZoneId.of("Europe/Luxembourg")),
            utc.withZoneSameInstant(ZoneId.of("Asia/Tokyo")),
            utc.withZoneSameInstant(ZoneOffset.ofHoursMinutes(5, 45)),
        };
        SunPosition reference = SolarCalculator.position(utc, LUXEMBOURG, Observer.SEA_LEVEL);
        for (ZonedDateTime t : same) {
            SunPosition p = SolarCalculator.position(t, LUXEMBOURG, Observer.SEA_LEVEL);
            assertEquals(reference.azimuthDegrees(), p.azimuthDegrees(), 1e-9, t.toString());
            assertEquals(reference.zenithDegrees(), p.zenithDegrees(), 1e-9, t.toString());
        }
        // one hour later the sun has moved: the zone is not simply ignored
        SunPosition later = SolarCalculator.position(utc.plusHours(1), LUXEMBOURG, Observer.SEA_LEVEL);
        assertTrue(Math.abs(later.azimuthDegrees() - reference.azimuthDegrees()) > 5);
    }

    @Test
    void refractionLiftsTheSunNearTheHorizonAndVanishesWithThinAir() {
        ZonedDateTime nearSunset = ZonedDateTime.parse("2024-06-21T19:30Z");
        SunPosition dense = SolarCalculator.position(nearSunset, LUXEMBOURG, Observer.SEA_LEVEL);
        SunPosition thin = SolarCalculator.position(nearSunset, LUXEMBOURG, Observer.SEA_LEVEL.withPressure(1e-3));
        double lift = dense.elevationDegrees() - thin.elevationDegrees();
        assertTrue(lift > 0.2 && lift < 0.7, "refraction near the horizon " + lift);
    }

    @Test
    void estimatedDeltaTIsPlausibleAndGivenDeltaTIsUsed() {
        SunAtInstant estimated = SunAtInstant.of(ZonedDateTime.parse("2024-06-21T12:00Z"), Observer.SEA_LEVEL);
        assertTrue(estimated.deltaTSeconds() > 60 && estimated.deltaTSeconds() < 80, "" + estimated.deltaTSeconds());
        SunAtInstant given = SunAtInstant.of(ZonedDateTime.parse("2024-06-21T12:00Z"),
                Observer.SEA_LEVEL.withDeltaT(69.2));
        assertEquals(69.2, given.deltaTSeconds());
        assertFalse(given.observer().isDeltaTEstimated());
    }

    @Test
    void badInputsAreRefusedWithMessages() {
        ZonedDateTime t = ZonedDateTime.parse("2024-06-21T12:00Z");
        assertMessage(() -> SolarCalculator.position(t, 91, 0, Observer.SEA_LEVEL), "latitude");
        assertMessage(() -> SolarCalculator.position(t, 0, 181, Observer.SEA_LEVEL), "longitude");
        assertMessage(() -> SolarCalculator.position(t, Double.NaN, 0, Observer.SEA_LEVEL), "latitude");
        assertMessage(() -> SolarCalculator.position(ZonedDateTime.parse("6001-01-01T00:00Z"), 0, 0,
                Observer.SEA_LEVEL.withDeltaT(0)), "-2000 to 6000");
        assertMessage(() -> SolarCalculator.position(ZonedDateTime.parse("3500-01-01T00:00Z"), 0, 0,
                Observer.SEA_LEVEL), "delta T");
        assertMessage(() -> Observer.SEA_LEVEL.withPressure(0), "pressure");
        assertMessage(() -> Observer.SEA_LEVEL.withTemperature(-300), "temperature");
        assertMessage(() -> Observer.atHeight(50_000), "height");
        // with ΔT given, a far year works
        SunPosition p = SolarCalculator.position(ZonedDateTime.parse("3500-01-01T00:00Z"), 0, 0,
                Observer.SEA_LEVEL.withDeltaT(8000));
        assertTrue(p.zenithDegrees() >= 0 && p.zenithDegrees() <= 180);
    }

    @Test
    void standardAtmosphereAtHeight() {
        // ISA (ICAO Doc 7488 tables): 1013.25 hPa and 15 °C at sea level; 898.75 hPa and 8.5 °C at 1000 m.
        assertEquals(1013.25, Observer.atHeight(0).pressureMillibars(), 1e-9);
        assertEquals(898.75, Observer.atHeight(1000).pressureMillibars(), 0.05);
        assertEquals(8.5, Observer.atHeight(1000).temperatureCelsius(), 1e-9);
    }

    static void assertMessage(org.junit.jupiter.api.function.Executable e, String fragment) {
        IllegalArgumentException ex = assertThrows(IllegalArgumentException.class, e);
        assertTrue(ex.getMessage().contains(fragment), "message '" + ex.getMessage() + "' should mention " + fragment);
    }

    private static void assertNear(ZonedDateTime expected, ZonedDateTime actual, long seconds) {
        long off = Math.abs(Duration.between(expected, actual).toSeconds());
        assertTrue(off <= seconds, "expected " + expected + " ± " + seconds + " s, got " + actual);
    }
}
