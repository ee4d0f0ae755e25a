package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

class MainTest {

    private static final Set<String> ALL = Set.of("help", "render", "hillshade", "tint", "shadows", "tiles", "info", "sun");

    @Test
    void aNamedSubcommandBuildsOnlyItsOwnModel() {
        assertEquals(Set.of("hillshade"), Main.commandLine(new String[] {"hillshade", "x.tif"}).getSubcommands()
                .keySet());
        assertEquals(Set.of("shadows"), Main.commandLine(new String[] {"shadows"}).getSubcommands().keySet());
    }

    @Test
    void helpOptionsAndUnknownNamesGetEveryCommand() {
        for (List<String> args : List.of(List.<String>of(), List.of("help", "render"), List.of("--help"),
                List.of("hillshad"), List.of("--version"))) {
            assertEquals(ALL, Main.commandLine(args.toArray(String[]::new)).getSubcommands().keySet(),
                    args.toString());
        }
        CliRun help = CliRun.of("--help");
        assertEquals(0, help.exitCode());
        for (String name : ALL) {
            assertTrue(help.out().contains("  " + name + " "), name + " missing from --help:\n" + help.out());
        }
        CliRun typo = CliRun.of("hillshad");
        assertEquals(2, typo.exitCode());
        assertTrue(typo.err().contains("Did you mean"), typo.err());
    }

    /** Options are listed in their groups, as declared (input, output, tint, hillshade, shadows, sun, threads). */
    @Test
    void helpListsTheOptionsInTheOrderTheyAreDeclared() {
        String all = CliRun.of("render", "--help").out();
        String help = all.substring(all.indexOf("\n      [FILE...]")); // the option list, not the synopsis
        String[] order = {"--window=", "--width=", "--height=", "--scale=", "--output=", "--tint=", "--hillshade=",
            "--z-factor=", "--xy-scale=", "--shadows=", "--shadow-intensity=", "--refraction=", "--sun-time=",
            "--sun-azimuth=", "--sun-elevation=", "--threads=", "--tile-size="};
        int at = -1;
        for (String option : order) {
            int next = help.indexOf(option, at + 1);
            assertTrue(next > at, option + " after the previous one in:\n" + help);
            at = next;
        }
    }
}
