package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import org.apache.sis.referencing.CRS;
import org.apache.sis.referencing.CommonCRS;
import org.apache.sis.referencing.IdentifiedObjects;
import org.apache.sis.util.Utilities;
import org.junit.jupiter.api.Test;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.crs.GeographicCRS;
import org.opengis.referencing.crs.ProjectedCRS;
import org.opengis.util.FactoryException;

class EsriPrjTest {

    @Test
    void projectedCrsIsOneLineOfWkt1ThatParsesBackToTheSameCrs() throws FactoryException {
        CoordinateReferenceSystem utm = CommonCRS.WGS84.universal(34, -117); // UTM 11N
        CrsInfo crs = new CrsInfo("WGS 84 / UTM zone 11N", 32611, CrsInfo.Kind.PROJECTED, 1.0, Ellipsoid.WGS84,
                utm, false);
        EsriPrj.Result result = EsriPrj.of(crs);
        String wkt = result.wkt().orElseThrow();
        assertNull(result.notice());
        assertTrue(wkt.startsWith("PROJCS[\"WGS 84 / UTM zone 11N\""), wkt); // WKT 1, not WKT 2's PROJCRS
        assertFalse(wkt.contains("\n"), wkt);
        assertTrue(wkt.contains("PARAMETER[\"central_meridian\", -117.0]"), wkt); // OGC names, ESRI reads them
        assertTrue(wkt.contains("UNIT[\"degree\", 0.017453292519943295]"), wkt); // common units: degrees
        CoordinateReferenceSystem back = CRS.fromWKT(wkt);
        assertTrue(back instanceof ProjectedCRS);
        assertTrue(Utilities.equalsIgnoreMetadata(utm, back), back.toString());
        assertEquals(Integer.valueOf(32611), IdentifiedObjects.lookupEPSG(back));
    }

    @Test
    void anEpsgCodeAloneIsEnoughWhenSisKnowsItOffline() throws FactoryException {
        EsriPrj.Result result = EsriPrj.of(CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84));
        String wkt = result.wkt().orElseThrow();
        assertTrue(wkt.startsWith("GEOGCS[\"WGS 84\""), wkt);
        CoordinateReferenceSystem back = CRS.fromWKT(wkt);
        assertTrue(back instanceof GeographicCRS);
        // east–north, the axis order of the grid and of every CRS a reader resolves
        assertTrue(Utilities.equalsIgnoreMetadata(CommonCRS.WGS84.normalizedGeographic(), back), back.toString());
    }

    @Test
    void unknownCrsGivesNoWktButANotice() {
        EsriPrj.Result result = EsriPrj.of(CrsInfo.UNKNOWN);
        assertTrue(result.wkt().isEmpty());
        assertTrue(result.notice().contains("unknown"), result.notice());

        EsriPrj.Result named = EsriPrj.of(CrsInfo.projected("My local grid", null, 1.0, null));
        assertTrue(named.wkt().isEmpty());
        assertTrue(named.notice().contains("My local grid"), named.notice());
    }

    @Test
    void anEpsgCodeWithoutDefinitionGivesANoticeNamingIt() {
        EsriPrj.Result result = EsriPrj.of(CrsInfo.projected("nonsense", 999_999, 1.0, null));
        assertTrue(result.wkt().isEmpty());
        assertTrue(result.notice().contains("EPSG:999999"), result.notice());
    }
}
