package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class MainTest {

    private static final Set<String> ALL = Set.of("help", "render", "view", "hillshade", "tint", "shadows",
            "skyview", "tiles", "info", "sun", "completion");

    @Test
    void aNamedSubcommandBuildsOnlyItsOwnModel() {
        assertEquals(Set.of("hillshade"), Main.commandLine(new String[] {"hillshade", "x.tif"}).getSubcommands()
                .keySet());
        assertEquals(Set.of("shadows"), Main.commandLine(new String[] {"shadows"}).getSubcommands().keySet());
    }

    /** Also {@code completion}, whose script covers every command. */
    @Test
    void helpOptionsAndUnknownNamesGetEveryCommand() {
        for (List<String> args : List.of(List.<String>of(), List.of("help", "render"), List.of("--help"),
                List.of("hillshad"), List.of("--version"), List.of("completion"))) {
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

    /**
     * The commands that write a file share their {@code @Command} attributes ({@link WritingCommandAttributes}):
     * the version, the exit status list, the options as declared with -h and -V last.
     */
    @Test
    void everyWritingCommandHasTheVersionAndTheExitStatusList() {
        String exitStatus = String.format("%nExit status:%n  0   written%n  1   an input could not be read or the output "
                + "not written%n  2   bad usage%n");
        for (String name : List.of("render", "hillshade", "tint", "shadows", "tiles")) {
            String help = CliRun.of(name, "--help").out();
            assertTrue(help.endsWith(exitStatus), name + ":\n" + help);
            assertTrue(help.indexOf("--verbose ") < help.indexOf("-h, --help"), name + ":\n" + help);
            CliRun version = CliRun.of(name, "--version");
            assertEquals(0, version.exitCode());
            assertTrue(version.out().startsWith("jdem846 "), name + ": " + version.out());
        }
    }

    /** render and tiles declare their scene options once ({@link SceneOptions}); tiles words --shadows its own way. */
    @Test
    void sharedOptionsKeepEachCommandsWording() {
        CommandLine all = Main.commandLine();
        String render = shadowsText(all.getSubcommands().get("render"));
        String tiles = shadowsText(all.getSubcommands().get("tiles"));
        assertTrue(render.endsWith("march (the article's ray march, fixed) or exact (the slow reference)."), render);
        assertTrue(tiles.endsWith("each tile reads the terrain toward the sun that can shade it, so shadows run on "
                + "across tiles."), tiles);
        for (String name : List.of("render", "tiles")) {
            CommandLine.Model.CommandSpec spec = all.getSubcommands().get(name).getCommandSpec();
            assertEquals("0.4", spec.findOption("--shadow-intensity").defaultValue(), name);
            assertTrue(String.join(" ", spec.findOption("--hillshade").description()).startsWith("jdem846"), name);
        }
        String help = CliRun.of("tiles", "--help").out();
        assertTrue(help.contains("so shadows run on across tiles."), help);
    }

    private static String shadowsText(CommandLine command) {
        return String.join(" ", command.getCommandSpec().findOption("--shadows").description());
    }
}
