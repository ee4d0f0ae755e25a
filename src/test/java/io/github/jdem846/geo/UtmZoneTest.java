package io.github.jdem846.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.util.stream.IntStream;
import org.apache.sis.referencing.CRS;
import org.junit.jupiter.api.Test;
import org.opengis.parameter.ParameterValueGroup;
import org.opengis.referencing.crs.ProjectedCRS;
import org.opengis.util.FactoryException;

/** The UTM zones read without Apache SIS, against Apache SIS's own definitions of the same EPSG codes. */
class UtmZoneTest {

    private static final int[][] FAMILIES = {{32601, 32660}, {32701, 32760}, {26901, 26923}, {25828, 25837}};

    @Test
    void everyCodeDescribesTheCrsApacheSisDefines() throws FactoryException {
        int checked = 0;
        for (int[] family : FAMILIES) {
            for (int code = family[0]; code <= family[1]; code++) {
                UtmZone zone = UtmZone.ofEpsg(code).orElseThrow();
                CrsInfo sis = CrsResolver.fromEpsg(code).orElseThrow();
                CrsInfo ours = zone.crsInfo();
                String at = "EPSG:" + code;
                assertNull(ours.sisCrs(), at);
                assertEquals(new CrsInfo(sis.name(), sis.epsg(), sis.kind(), sis.linearUnitMeters(), sis.ellipsoid(),
                        null, false), ours, at);
                assertEquals(sis.sisCrs(), CrsResolver.complete(ours).sisCrs(), at);

                ProjectedCRS crs = (ProjectedCRS) CRS.forCode(at);
                assertEquals("Transverse Mercator", crs.getConversionFromBase().getMethod().getName().getCode(), at);
                ParameterValueGroup p = crs.getConversionFromBase().getParameterValues();
                assertEquals(zone.centralMeridian(), p.parameter("Longitude of natural origin").doubleValue(), 0, at);
                assertEquals(0, p.parameter("Latitude of natural origin").doubleValue(), 0, at);
                assertEquals(UtmZone.CENTRAL_SCALE, p.parameter("Scale factor at natural origin").doubleValue(), 0, at);
                assertEquals(UtmZone.FALSE_EASTING, p.parameter("False easting").doubleValue(), 0, at);
                assertEquals(zone.south() ? 10_000_000 : 0, p.parameter("False northing").doubleValue(), 0, at);
                checked++;
            }
        }
        assertEquals(153, checked);
    }

    @Test
    void otherCodesAreNotZones() {
        IntStream.of(0, 4326, 3857, 2193, 32600, 32661, 32700, 32761, 26900, 26924, 25827, 25838, 26711, 32201)
                .forEach(code -> assertTrue(UtmZone.ofEpsg(code).isEmpty(), "EPSG:" + code));
    }

    @Test
    void scaleFactorFollowsTheEllipsoidalProjection() {
        // The spherical formula against Apache SIS's ellipsoidal transverse Mercator (the ground size of one
        // cell, GridGeometry.groundScaleFactor) from the central meridian to 1 500 km east and west, north and
        // south: within 1 % of the departure from 1, plus 2e-5.
        for (int code : new int[] {32611, 32733, 25832}) {
            UtmZone zone = UtmZone.ofEpsg(code).orElseThrow();
            CrsInfo crs = CrsResolver.fromEpsg(code).orElseThrow();
            for (double northing : new double[] {zone.south() ? 6_000_000 : 1_000_000, zone.south() ? 9_000_000
                    : 6_500_000}) {
                for (double dx = -1_500_000; dx <= 1_500_000; dx += 250_000) {
                    double easting = UtmZone.FALSE_EASTING + dx;
                    GridGeometry g = new GridGeometry(2, 1, easting - 1, northing + 0.5, 1, 1, crs,
                            PixelAnchor.CORNER);
                    double exact = g.groundScaleFactor().orElseThrow();
                    double spherical = zone.scaleFactorAt(easting);
                    String at = "EPSG:" + code + " E " + easting + " N " + northing;
                    assertEquals(exact, spherical, 0.01 * Math.abs(exact - 1) + 2e-5, at);
                }
            }
        }
    }

    @Test
    void aUtmGeoTiffIsReadWithoutApacheSisAndLocatedWithIt() throws IOException {
        GridGeometry g = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.BIG_TUJUNGA + ".tif")).geometry();
        assertNull(g.crs().sisCrs());
        assertEquals(UtmZone.ofEpsg(32611).orElseThrow().crsInfo(), g.crs());
        GridGeometry withSis = new GridGeometry(g.width(), g.height(), g.originX(), g.originY(), g.cellWidth(),
                g.cellHeight(), CrsResolver.fromEpsg(32611).orElseThrow(), PixelAnchor.CORNER);
        for (int[] cell : new int[][] {{0, 0}, {g.width() - 1, g.height() - 1}, {600, 300}}) {
            assertEquals(withSis.cellCenterLatLon(cell[0], cell[1]).orElseThrow(),
                    g.cellCenterLatLon(cell[0], cell[1]).orElseThrow());
        }
    }
}
