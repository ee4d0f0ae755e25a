package io.github.jdem846.sun;

import io.github.jdem846.geo.LatLon;
import static io.github.jdem846.sun.SolarCalculatorTest.assertMessage;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.Ellipsoid;
import org.junit.jupiter.api.Test;

class LatLonAndBodyTest {

    @Test
    void parsesPlaces() {
        assertEquals(new LatLon(49.61, 6.13), LatLon.parse("49.61,6.13"));
        assertEquals(new LatLon(-33.92, 18.42), LatLon.parse(" -33.92 , 18.42 "));
        assertEquals(new LatLon(90, -180), LatLon.parse("90,-180"));
    }

    @Test
    void refusesBadPlaces() {
        assertMessage(() -> LatLon.parse("91,0"), "latitude must be between -90 and 90");
        assertMessage(() -> LatLon.parse("-90.5,0"), "latitude");
        assertMessage(() -> LatLon.parse("0,180.5"), "longitude must be between -180 and 180");
        assertMessage(() -> LatLon.parse("0,200"), "-160");
        assertMessage(() -> LatLon.parse("abc"), "LAT,LON");
        assertMessage(() -> LatLon.parse("1,2,3"), "LAT,LON");
        assertMessage(() -> LatLon.parse("north,2"), "latitude 'north'");
        assertMessage(() -> LatLon.parse("1,"), "longitude ''");
        assertMessage(() -> LatLon.parse("NaN,0"), "not a number");
        assertMessage(() -> LatLon.parse("1e400,0"), "not a number");
        assertMessage(() -> LatLon.parse(null), "LAT,LON");
    }

    @Test
    void wrapsLongitudes() {
        assertEquals(-175, LatLon.wrapLongitude(185), 1e-12);
        assertEquals(-180, LatLon.wrapLongitude(180), 1e-12);
        assertEquals(179, LatLon.wrapLongitude(-181), 1e-12);
        assertEquals(10, LatLon.wrapLongitude(730), 1e-12);
    }

    @Test
    void bodies() {
        assertSame(Body.EARTH, Body.named("Earth"));
        assertSame(Body.MOON, Body.named(" moon"));
        assertSame(Body.MARS, Body.named("MARS"));
        assertEquals(1_737_400, Body.MOON.radiusMeters(), 1e-6);
        assertEquals(Ellipsoid.WGS84, Body.EARTH.ellipsoid());
        assertEquals(1000, Body.sphere(1000).radiusMeters(), 1e-9);
        assertSame(Body.EARTH, Body.EARTH.requireSunByDateAndTime());
        assertTrue(Body.EARTH.isEarth());
        assertFalse(Body.sphere(6_371_000).isEarth());
        assertMessage(() -> Body.named("venus"), "earth, moon or mars");
        assertMessage(() -> Body.sphere(-1), "radius");
        assertMessage(Body.MOON::requireSunByDateAndTime, "Earth only");
        assertMessage(Body.MARS::requireSunByDateAndTime, "Mars");
    }
}
