package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.apache.sis.referencing.CommonCRS;
import org.junit.jupiter.api.Test;

class GdalAuxXmlTest {

    @Test
    void axisMappingPutsImageXOnTheEastAxis() {
        // EPSG:4326 is latitude first: image x (longitude) is CRS axis 2, as gdal_translate writes it.
        assertEquals("2,1", GdalAuxXml.axisMapping(CommonCRS.WGS84.geographic()));
        assertEquals("1,2", GdalAuxXml.axisMapping(CommonCRS.WGS84.normalizedGeographic()));
        assertEquals("1,2", GdalAuxXml.axisMapping(CommonCRS.WGS84.universal(34, -117)));
    }

    @Test
    void wktIsEscapedInsideTheSrsElement() {
        String xml = GdalAuxXml.of("GEOGCS[\"a<b&c\"]", CommonCRS.WGS84.geographic());
        assertTrue(xml.startsWith("<PAMDataset>\n  <SRS dataAxisToSRSAxisMapping=\"2,1\">"), xml);
        assertTrue(xml.contains(">GEOGCS[\"a&lt;b&amp;c\"]</SRS>"), xml);
        assertTrue(xml.strip().endsWith("</PAMDataset>"), xml);
    }
}
