package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import org.junit.jupiter.api.Test;

class MethodNamesTest {

    @Test
    void namesRoundTripAndUnknownNamesSayWhatIsAllowed() {
        for (HillshadeMethod m : HillshadeMethod.values()) {
            assertEquals(m, MethodNames.hillshade(MethodNames.of(m).toUpperCase()));
        }
        assertEquals("multidirectional", MethodNames.of(HillshadeMethod.MULTIDIRECTIONAL));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MethodNames.hillshade("zevenbergen"));
        assertTrue(e.getMessage().contains("jdem846") && e.getMessage().contains("horn"), e.getMessage());
    }

    @Test
    void shadowAlgorithmNamesRoundTripAndUnknownNamesSayWhatIsAllowed() {
        for (ShadowAlgorithm a : ShadowAlgorithm.values()) {
            assertEquals(a, MethodNames.shadows(" " + MethodNames.of(a).toUpperCase() + " "));
        }
        assertEquals("sweep", MethodNames.of(ShadowAlgorithm.SWEEP));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MethodNames.shadows("raycast"));
        assertEquals("unknown shadow algorithm 'raycast'; expected one of march, sweep, exact, none", e.getMessage());
    }
}
